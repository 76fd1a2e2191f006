// Use case: render a scene file (the course's format) with the painter's algorithm, both ways.
//
//   render_scene SCENE.json OUT_PREFIX     → OUT_PREFIX_flat.png, OUT_PREFIX_gouraud.png
#include <cstdio>
#include <exception>
#include <string>

#include "io/scene_json.hpp"
#include "src/painter.hpp"
#include "viz/image_file.hpp"

int main(int argc, char** argv) {
  using namespace scantrace;
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s SCENE.json OUT_PREFIX\n", argv[0]);
    return 2;
  }
  try {
    const Scene scene = load_scene(argv[1]);
    // One image and one scratch for both renders: the second reuses their storage and
    // allocates nothing (render(scene, options) would return a fresh image each time).
    RgbImage image;
    RenderScratch scratch;
    for (Shading shading : {Shading::flat, Shading::gouraud}) {
      const RenderStats stats = render(image, scene, FillOptions{.shading = shading}, scratch);
      const std::string out = std::string(argv[2]) + "_" + to_string(shading) + ".png";
      write_png(image, out);
      std::printf("%s: %lld triangles drawn, %lld skipped, %lld pixels -> %s\n", to_string(shading),
                  stats.triangles_filled, stats.triangles_skipped, stats.pixels, out.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_scene: %s\n", e.what());
    return 1;
  }
}
