#pragma once
// The course's render: every face of the scene filled in painter's order (docs/design.md §2), or,
// when FillOptions::visibility asks for it, in face order through a depth buffer
// (zbuffer_canvas.hpp).
#include <vector>

#include "scanline_fill.hpp"
#include "scene.hpp"
#include "zbuffer_canvas.hpp"

namespace scantrace {

// Face depth = mean of its three vertex depths, computed in double; farthest (largest) first, and
// faces of equal depth keep their order in the scene (stable), so the result is reproducible.
std::vector<double> face_depths(const Scene& scene);
std::vector<int> painter_order(const std::vector<double>& face_depths);

struct RenderStats {
  long long triangles_filled = 0;
  long long triangles_skipped = 0;  // for any reason but culling
  long long triangles_culled = 0;   // FillOptions::cull
  long long pixels = 0;             // written by the fill (z-buffer: before the depth test)

  void count(const FillResult& r) {
    (r.skipped == SkipReason::none     ? triangles_filled
     : r.skipped == SkipReason::culled ? triangles_culled
                                       : triangles_skipped) += 1;
    pixels += r.pixels;
  }
};

// Fills the faces of `scene` onto `canvas` (which the caller has cleared to the background).
// The scene must be valid (see validate()).
template <Canvas C, FillTracer Tracer = NoTracer>
RenderStats render_into(C& canvas, const Scene& scene, const FillOptions& opt, Tracer& tracer) {
  const std::vector<double> depth = face_depths(scene);
  FillScratch scratch;
  RenderStats stats;
  for (int f : painter_order(depth)) {
    const FaceCorners c = corners_of(scene, scene.faces[f]);
    stats.count(
        fill_polygon(canvas, PolygonInput{c.points, c.colors, f, depth[f]}, opt, scratch, tracer));
  }
  return stats;
}

// The faces in scene order through the depth buffer of `canvas`: no sort, and the order does not
// matter except for exact depth ties (the first face drawn keeps the pixel).
template <class P, FillTracer Tracer = NoTracer>
RenderStats render_zbuffer_into(ZBufferCanvas<P>& canvas, const Scene& scene,
                                const FillOptions& opt, Tracer& tracer) {
  const std::vector<double> depth = face_depths(scene);
  const SubpixelGrid grid(opt.subpixel_bits);
  FillScratch scratch;
  RenderStats stats;
  for (int f = 0; f < static_cast<int>(scene.faces.size()); ++f) {
    const FaceCorners c = corners_of(scene, scene.faces[f]);
    const std::array<double, 3> d = corner_depths(scene, scene.faces[f]);
    if (grid.valid()) canvas.begin_triangle(c.points, d, grid);
    stats.count(fill_polygon(canvas, PolygonInput{c.points, c.colors, f, depth[f], d}, opt, scratch,
                             tracer));
  }
  return stats;
}

// The scene on a fresh canvas of its size and background colour, in pixels of type P: Rgb32f is
// the course's float canvas, Bgr8 the 8-bit image that files, videos and OpenCV use.
template <class P = Rgb32f, FillTracer Tracer = NoTracer>
Image<P> render(const Scene& scene, const FillOptions& opt, Tracer& tracer,
                RenderStats* stats = nullptr) {
  Image<P> image(scene.width, scene.height, P::from(scene.background));
  RenderStats s;
  if (opt.visibility == Visibility::zbuffer) {
    // Only a pixel-level trace reads the per-pixel outcomes of the depth test.
    ZBufferCanvas<P> canvas(image, kTraceHooks && Tracer::max_level >= TraceLevel::pixel);
    s = render_zbuffer_into(canvas, scene, opt, tracer);
  } else {
    ImageCanvas<P> canvas(image);
    s = render_into(canvas, scene, opt, tracer);
  }
  if (stats) *stats = s;
  return image;
}

template <class P = Rgb32f>
Image<P> render(const Scene& scene, const FillOptions& opt = {}, RenderStats* stats = nullptr) {
  NoTracer none;
  return render<P>(scene, opt, none, stats);
}

}  // namespace scantrace
