#pragma once
// The course's render: every face of the scene filled in painter's order (design.md §2).
#include <vector>

#include "scanline_fill.hpp"
#include "scene.hpp"

namespace scantrace {

// Face depth = mean of its three vertex depths, computed in double; farthest (largest) first, and
// faces of equal depth keep their order in the scene (stable), so the result is reproducible.
std::vector<double> face_depths(const Scene& scene);
std::vector<int> painter_order(const std::vector<double>& face_depths);

struct RenderStats {
  long long triangles_filled = 0;
  long long triangles_skipped = 0;
  long long pixels = 0;
};

// Fills the faces of `scene` onto `canvas` (which the caller has cleared to the background).
// The scene must be valid (see validate()).
template <Canvas C, FillTracer Tracer = NoTracer>
RenderStats render_into(C& canvas, const Scene& scene, const FillOptions& opt, Tracer& tracer) {
  const std::vector<double> depth = face_depths(scene);
  FillScratch scratch;
  RenderStats stats;
  for (int f : painter_order(depth)) {
    const auto& face = scene.faces[f];
    const std::array<Vec2, 3> v{scene.vertices[face[0]], scene.vertices[face[1]],
                                scene.vertices[face[2]]};
    const std::array<Color, 3> c{scene.vcolors[face[0]], scene.vcolors[face[1]],
                                 scene.vcolors[face[2]]};
    const FillResult r =
        fill_polygon(canvas, PolygonInput{v, c, f, depth[f]}, opt, scratch, tracer);
    (r.skipped == SkipReason::none ? stats.triangles_filled : stats.triangles_skipped) += 1;
    stats.pixels += r.pixels;
  }
  return stats;
}

// The scene on a fresh canvas of its size and background colour, in pixels of type P: Rgb32f is
// the course's float canvas, Bgr8 the 8-bit image that files, videos and OpenCV use.
template <class P = Rgb32f, FillTracer Tracer = NoTracer>
Image<P> render(const Scene& scene, const FillOptions& opt, Tracer& tracer,
                RenderStats* stats = nullptr) {
  Image<P> image(scene.width, scene.height, P::from(scene.background));
  ImageCanvas<P> canvas(image);
  const RenderStats s = render_into(canvas, scene, opt, tracer);
  if (stats) *stats = s;
  return image;
}

template <class P = Rgb32f>
Image<P> render(const Scene& scene, const FillOptions& opt = {}, RenderStats* stats = nullptr) {
  NoTracer none;
  return render<P>(scene, opt, none, stats);
}

}  // namespace scantrace
