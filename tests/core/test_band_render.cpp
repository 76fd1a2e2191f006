// The parallel band render draws exactly what the single-threaded render draws: every band
// receives the same writes in the same painter's order (z-buffered: the same depth tests in scene
// order), so the images are equal bit for bit.
#include <catch2/catch.hpp>

#include <filesystem>

#include "demo/demo_scene.hpp"
#include "src/band_render.hpp"
#include "src/splitmix64.hpp"

namespace {

using namespace scantrace;

// Overlapping triangles of every size at random depths, some far off the canvas, some crossing
// many bands, some thinner than a row: the cases where a band's clipping could differ from the
// canvas's.
Scene overlapping_scene(std::uint64_t seed, int width, int height, int faces) {
  SplitMix64 rng(seed);
  Scene s;
  s.width = width;
  s.height = height;
  s.background = {1, 1, 1};
  for (int f = 0; f < faces; ++f) {
    const double cx = rng.uniform(-50, width + 50), cy = rng.uniform(-50, height + 50);
    const double size = f % 50 == 0 ? 1e6 : rng.uniform(0.3, 120);
    for (int k = 0; k < 3; ++k) {
      s.vertices.push_back({cx + rng.uniform(-size, size), cy + rng.uniform(-size, size)});
      s.vcolors.push_back({rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)});
      s.depth.push_back(rng.uniform(0, 10));
    }
    s.faces.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  }
  return s;
}

}  // namespace

TEST_CASE("band render: bit-identical to the single-threaded render", "[band]") {
  const Scene scenes[] = {demo_scene(), overlapping_scene(7, 300, 211, 2000),
                          overlapping_scene(8, 64, 17, 300)};
  for (const Scene& scene : scenes)
    for (Shading shading : {Shading::flat, Shading::gouraud})
      for (FillRule rule : {FillRule::top_left, FillRule::closed})
        for (Visibility visibility : {Visibility::painter, Visibility::zbuffer}) {
          const FillOptions opt{.shading = shading, .fill_rule = rule, .visibility = visibility};
          RenderStats one, many;
          const Bgr8Image expected = render<Bgr8>(scene, opt, &one);
          for (int threads : {1, 2, 3, 7}) {
            INFO(scene.faces.size() << " faces, " << threads << " threads, " << to_string(shading)
                                    << ", " << to_string(rule) << ", " << to_string(visibility));
            CHECK(render_parallel<Bgr8>(scene, opt, threads, &many) == expected);
            CHECK(many.pixels == one.pixels);
            CHECK(many.triangles_filled == one.triangles_filled);
            CHECK(many.triangles_skipped == one.triangles_skipped);
          }
          CHECK(render_parallel<Rgb32f>(scene, opt, 2) == render<Rgb32f>(scene, opt));
        }
}

TEST_CASE("a render into the caller's image equals a fresh render, whatever the image held",
          "[band][painter]") {
  // One image and one scratch for every render, as the bench and an animation keep them: the
  // scenes change size (the storage is replaced) and repeat a size (it is kept, and must be
  // cleared: none of these scenes covers its whole canvas), and the depths, the order and the
  // fill's scratch carry over from a different scene each time.
  const Scene scenes[] = {overlapping_scene(7, 300, 211, 2000), overlapping_scene(8, 64, 17, 300),
                          overlapping_scene(9, 64, 17, 40), demo_scene(),
                          overlapping_scene(10, 300, 211, 500)};
  Bgr8Image image(5, 5, Bgr8{1, 2, 3});
  RgbImage float_image;
  RenderScratch scratch;
  for (int pass = 0; pass < 2; ++pass)
    for (const Scene& scene : scenes)
      for (Visibility visibility : {Visibility::painter, Visibility::zbuffer})
        for (Shading shading : {Shading::flat, Shading::gouraud}) {
          const FillOptions opt{.shading = shading, .visibility = visibility};
          INFO(scene.width << "x" << scene.height << ", " << scene.faces.size() << " faces, "
                           << to_string(shading) << ", " << to_string(visibility));
          RenderStats fresh_stats;
          const Bgr8Image fresh = render<Bgr8>(scene, opt, &fresh_stats);
          const RenderStats stats = render(image, scene, opt, scratch);
          CHECK(image == fresh);
          CHECK(stats.pixels == fresh_stats.pixels);
          CHECK(stats.triangles_filled == fresh_stats.triangles_filled);
          CHECK(render_parallel(image, scene, opt, 2, scratch).pixels == fresh_stats.pixels);
          CHECK(image == fresh);
          render(float_image, scene, opt, scratch);
          CHECK(float_image == render<Rgb32f>(scene, opt));
        }
}
