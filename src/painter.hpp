#pragma once
// The course's render: every face of the scene filled in painter's order (docs/design.md §2), or,
// when FillOptions::visibility asks for it, in face order through a depth buffer
// (zbuffer_canvas.hpp).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

#include "fast/coverage_mask.hpp"
#include "fast/depth_tiles.hpp"
#include "fast/occlusion_canvas.hpp"
#include "fast/occlusion_choice.hpp"
#include "scanline_fill.hpp"
#include "scene.hpp"
#include "fast/small_triangle_batch.hpp"
#include "zbuffer_canvas.hpp"

namespace scantrace {

// Face depth = mean of its three vertex depths, computed in double; farthest (largest) first, and
// faces of equal depth keep their order in the scene (stable), so the result is reproducible.
std::vector<double> face_depths(const Scene& scene);
std::vector<int> painter_order(const std::vector<double>& face_depths);

// The radix sort's buffers (keys, a second copy of keys and indices, digit counts), kept by a
// caller who sorts again so that a sort of as many faces allocates nothing.
struct PainterSortBuffers {
  std::vector<std::uint32_t> key, key_tmp;
  std::vector<int> order_tmp;
  std::vector<std::uint32_t> count;
};
void face_depths(const Scene& scene, std::vector<double>& depth);
void painter_order(std::span<const double> face_depths, std::vector<int>& order,
                   PainterSortBuffers& buffers);

// Everything a render needs besides the image: the face depths, the painter's order and its sort
// buffers, the fill's scratch and the z-buffer. A caller that renders more than once (the bench,
// an animation, a viewer) keeps one, and a warm render then allocates nothing.
struct RenderScratch {
  std::vector<double> depth;
  std::vector<int> order;
  PainterSortBuffers sort;
  FillScratch fill;
  std::vector<double> zbuffer;  // Visibility::zbuffer: the depth per pixel
  CoverageMask coverage;        // Occlusion::near_to_far: the pixels already final
  // The z-buffer near to far: which face each pixel's depth came from, and the tiles' bounds.
  std::vector<int> owner;
  DepthTiles depth_tiles;
  std::vector<float> overdraw_cells;  // Occlusion::automatic: estimated_overdraw's grid
};

struct RenderStats {
  long long triangles_filled = 0;   // near to far: those of which a pixel is seen
  long long triangles_skipped = 0;  // for any reason but culling and being hidden (near to far:
                                    // also a face that owns no pixel)
  long long triangles_culled = 0;   // FillOptions::cull
  // Pixels written by the fill: far to near, every pixel of every face, so that a pixel painted
  // over counts each time; near to far, each pixel once; z-buffer, before the depth test.
  long long pixels = 0;

  // Which way the render ran (FillOptions::occlusion, automatic resolved by choose_occlusion; a
  // traced render is far to near).
  Occlusion path = Occlusion::far_to_near;
  // Near to far: faces of which no pixel is seen, all hidden by nearer faces; of them, those
  // rejected from their bounding box before any set-up; and the pixels of the faces that were set
  // up that nearer faces already covered, which the fill clipped away (the writes it saved, not
  // counting the rejected faces, whose pixels are never counted). A face that owns no pixel (a
  // sliver between pixel centres) is hidden when the box test rejects it and skipped when it is
  // set up; the parallel render tests each band's part of the box, so with several threads the
  // two counts may trade such faces (their sum, and every other count, is the same).
  long long triangles_hidden = 0;
  long long triangles_rejected = 0;
  long long pixels_clipped = 0;

  void count(const FillResult& r) {
    if (r.skipped == SkipReason::hidden) {  // the z-buffer near to far: rejected before set-up
      ++triangles_hidden, ++triangles_rejected;
      return;
    }
    (r.skipped == SkipReason::none     ? triangles_filled
     : r.skipped == SkipReason::culled ? triangles_culled
                                       : triangles_skipped) += 1;
    pixels += r.pixels;
  }
  // A face of the near-to-far render, of which `visible` pixels were written.
  void count(const FillResult& r, long long visible) {
    if (r.skipped == SkipReason::hidden) {
      ++triangles_hidden, ++triangles_rejected;
    } else if (r.skipped == SkipReason::none) {
      // A face that owns no pixel (a sliver between pixel centres) draws nothing: skipped.
      ++(visible > 0 ? triangles_filled : r.pixels > 0 ? triangles_hidden : triangles_skipped);
      pixels += visible;
      pixels_clipped += r.pixels - visible;
    } else {
      count(r);
    }
  }
};

// The order a render draws in, into scratch.order, with the face depths into scratch.depth: the
// painter's (farthest first; nearest first, the same order reversed, for the near-to-far render),
// or for the z-buffer the scene's.
void drawing_order(const Scene& scene, Visibility visibility, RenderScratch& scratch,
                   Occlusion occlusion = Occlusion::far_to_near);

// A canvas with a depth buffer (zbuffer_canvas.hpp): each face's depth plane is set up before it
// is filled.
template <class C>
concept DepthBufferedCanvas = requires(C& c, std::span<const Vec2> v, std::span<const double> d,
                                       const SubpixelGrid& g) {
  c.begin_triangle(v, d, g);
};

namespace detail {

// Whether fill_faces may set faces up kTriangleBatch at a time (fast/small_triangle_batch.hpp): an
// untraced (kUntraced) flat fill of the exact method under the top-left rule (batchable), onto
// any canvas.
template <class Tracer>
constexpr bool kUntraced = std::is_same_v<std::remove_cvref_t<Tracer>, NoTracer>;

inline bool batchable(const FillOptions& opt) {
  return opt.method == Method::exact && opt.fill_rule == FillRule::top_left &&
         opt.shading == Shading::flat && SubpixelGrid(opt.subpixel_bits).valid();
}

// fill_faces for a batchable fill: each batch of faces is set up in SIMD lanes, then drawn in
// order, each face the batch takes by the small path and every other one by fill_polygon, which
// decides it as it always does. The faces, the order and every pixel are fill_faces's.
template <Canvas C, class Done>
void fill_faces_batched(C& canvas, const Scene& scene, std::span<const int> faces,
                        std::span<const double> depth, const FillOptions& opt, FillScratch& scratch,
                        Done&& done) {
  const BatchTarget target{opt.subpixel_bits, canvas.width(), canvas_rows(canvas), opt.cull};
  [[maybe_unused]] const SubpixelGrid grid(opt.subpixel_bits);
  TriangleBatch in{};
  BatchSetup out;
  NoTracer none;
  const std::size_t n = faces.size();
  for (std::size_t i = 0; i < n; i += kTriangleBatch) {
    const int m = static_cast<int>(std::min<std::size_t>(kTriangleBatch, n - i));
    // The next batch's indices and corners fetched while this one is set up (fill_faces says why).
    for (int k = 0; k < m && i + kTriangleBatch + k < n; ++k) {
      const auto& ahead = scene.faces[faces[i + kTriangleBatch + k]];
      for (int c = 0; c < 3; ++c) {
        __builtin_prefetch(&scene.vertices[ahead[c]]);
        __builtin_prefetch(&scene.vcolors[ahead[c]]);
      }
    }
    for (int k = 0; k < m; ++k) {
      const auto& face = scene.faces[faces[i + k]];
      for (int c = 0; c < 3; ++c) {
        const Vec2 v = scene.vertices[face[c]];
        const Color col = scene.vcolors[face[c]];
        in.x[c][k] = v.x, in.y[c][k] = v.y;
        in.r[c][k] = col.r, in.g[c][k] = col.g, in.b[c][k] = col.b;
      }
    }
    small_triangle_batch(in, target, out);
    for (int k = 0; k < m; ++k) {
      const int f = faces[i + k];
      if constexpr (CoverageCanvas<C>) {
        // Near to far: a face whose box nearer faces already cover is not drawn. This asks the
        // coverage as the faces before it left it, so it runs here, face by face, in order (the
        // batch has set up such a face for nothing: an eighth of a batch).
        const std::array<Vec2, 3> v = in.corners(k);
        if (!canvas.begin_face(v)) {
          done(f, FillResult{SkipReason::hidden, 0, 0});
          continue;
        }
      }
      // The z-buffer: the face's depth plane, then the test that rejects a face nearer ones
      // already hide everywhere (fill_faces's), face by face and in order, as above.
      [[maybe_unused]] std::array<double, 3> d{};
      if constexpr (DepthBufferedCanvas<C>) {
        d = corner_depths(scene, scene.faces[f]);
        const std::array<Vec2, 3> v = in.corners(k);
        canvas.begin_triangle(v, d, grid);
        if (!canvas.admit(f, v)) {
          done(f, FillResult{SkipReason::hidden, 0, 0});
          continue;
        }
      }
      if (out.small[k] != 0) {
        done(f, fill_small_triangle(canvas, out.triangle(k), out.flat(k), scratch.flat_row));
      } else {
        const FaceCorners c = corners_of(scene, scene.faces[f]);
        PolygonInput input{c.points, c.colors, f, depth[f]};
        if constexpr (DepthBufferedCanvas<C>) input.vertex_depths = d;
        done(f, fill_polygon(canvas, input, opt, scratch, none));
      }
    }
  }
}

}  // namespace detail

// The faces listed in `faces`, in that order, filled onto `canvas`; `done(face, result)` sees
// each result. The one face loop of every render: the whole image or a band of it
// (band_render.hpp), painter's or z-buffered.
template <Canvas C, FillTracer Tracer, class Done>
void fill_faces(C& canvas, const Scene& scene, std::span<const int> faces,
                std::span<const double> depth, const FillOptions& opt, FillScratch& scratch,
                Tracer& tracer, Done&& done) {
  if constexpr (detail::kUntraced<Tracer>)
    if (detail::batchable(opt))
      return detail::fill_faces_batched(canvas, scene, faces, depth, opt, scratch, done);
  const SubpixelGrid grid(opt.subpixel_bits);
  // Faces come in depth order, scattered over the scene's arrays, and a small face costs less
  // than fetching its corners from memory: its indices are fetched 2·kAhead faces ahead, and its
  // positions and colours kAhead faces ahead, by when its indices have arrived.
  constexpr std::size_t kAhead = 8;
  const std::size_t n = faces.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (i + 2 * kAhead < n) __builtin_prefetch(&scene.faces[faces[i + 2 * kAhead]]);
    if (i + kAhead < n) {
      const int g = faces[i + kAhead];
      if (!depth.empty()) __builtin_prefetch(&depth[g]);
      const auto& ahead = scene.faces[g];
      for (int k = 0; k < 3; ++k) {
        __builtin_prefetch(&scene.vertices[ahead[k]]);
        __builtin_prefetch(&scene.vcolors[ahead[k]]);
      }
    }
    const int f = faces[i];
    if constexpr (CoverageCanvas<C>) {
      // Near to far: a face whose box nearer faces already cover is not set up at all.
      const auto& face = scene.faces[f];
      const std::array<Vec2, 3> v{scene.vertices[face[0]], scene.vertices[face[1]],
                                  scene.vertices[face[2]]};
      if (!canvas.begin_face(v)) {
        done(f, FillResult{SkipReason::hidden, 0, 0});
        continue;
      }
    }
    const FaceCorners c = corners_of(scene, scene.faces[f]);
    if constexpr (DepthBufferedCanvas<C>) {
      const std::array<double, 3> d = corner_depths(scene, scene.faces[f]);
      if (grid.valid()) canvas.begin_triangle(c.points, d, grid);
      // Faces in any order (near to far): one that cannot pass a depth test is not set up.
      if (!canvas.admit(f, c.points)) {
        done(f, FillResult{SkipReason::hidden, 0, 0});
        continue;
      }
      done(f, fill_polygon(canvas, PolygonInput{c.points, c.colors, f, depth[f], d}, opt, scratch,
                           tracer));
    } else {
      done(f, fill_polygon(canvas, PolygonInput{c.points, c.colors, f, depth[f]}, opt, scratch,
                           tracer));
    }
  }
}

// The faces listed in `faces` (nearest first) onto an OcclusionCanvas, then the background where
// none drew; `done(face, result, visible)` sees each result with the pixels it wrote.
template <class P, class Done>
void fill_near_to_far(OcclusionCanvas<P>& canvas, const Scene& scene, std::span<const int> faces,
                      std::span<const double> depth, const FillOptions& opt, FillScratch& scratch,
                      Done&& done) {
  NoTracer none;
  long long seen = canvas.written();
  fill_faces(canvas, scene, faces, depth, opt, scratch, none, [&](int f, const FillResult& r) {
    const long long now = canvas.written();
    done(f, r, now - seen);
    seen = now;
  });
  canvas.finish(P::from(scene.background));
}

namespace detail {

// Fills the faces of `scene` onto `canvas` (which the caller has cleared to the background) in
// the order `visibility` draws them: the painter's, or scene order through the depth buffer of a
// ZBufferCanvas (no sort; the order matters only for exact depth ties, where the first face drawn
// keeps the pixel). The scene must be valid (see validate()).
template <Canvas C, FillTracer Tracer>
RenderStats render_into(C& canvas, const Scene& scene, Visibility visibility,
                        const FillOptions& opt, RenderScratch& scratch, Tracer& tracer) {
  drawing_order(scene, visibility, scratch);
  RenderStats stats;
  fill_faces(canvas, scene, scratch.order, scratch.depth, opt, scratch.fill, tracer,
             [&](int, const FillResult& r) { stats.count(r); });
  return stats;
}

// The z-buffered render of `scene` into `image` (cleared to the background), the faces nearest
// first in the painter's order reversed: most pixels then get their final depth from the first
// face that reaches them, and a face whose box the tiles show all nearer is rejected before its
// set-up. The image is the scene-order render's bit for bit: a pixel's depth is the same minimum,
// and an exact tie goes to the face first in the scene (ZBufferCanvas's owner buffer).
template <class P>
RenderStats render_zbuffer_near_to_far(Image<P>& image, const Scene& scene, const FillOptions& opt,
                                       RenderScratch& scratch) {
  const auto pixels = static_cast<std::size_t>(scene.width) * scene.height;
  scratch.zbuffer.assign(pixels, std::numeric_limits<double>::infinity());
  scratch.owner.assign(pixels, -1);
  scratch.depth_tiles.reset(scene.width, scene.height);
  drawing_order(scene, Visibility::painter, scratch, Occlusion::near_to_far);
  ZBufferCanvas<P> canvas(image, scratch.zbuffer, scratch.owner, scratch.depth_tiles);
  RenderStats stats;
  stats.path = Occlusion::near_to_far;
  NoTracer none;
  fill_faces(canvas, scene, scratch.order, scratch.depth, opt, scratch.fill, none,
             [&](int, const FillResult& r) { stats.count(r); });
  return stats;
}

}  // namespace detail

// The scene into the caller's `image`, which becomes the scene's size and is cleared to its
// background, keeping its storage when the size is unchanged (Image::reset). With the same
// `scratch` every time, a render after the first allocates nothing: what an animation, a viewer
// or a benchmark wants.
template <class P, FillTracer Tracer = NoTracer>
RenderStats render(Image<P>& image, const Scene& scene, const FillOptions& opt,
                   RenderScratch& scratch, Tracer& tracer) {
  // A traced render is far to near: the trace shows the course's algorithm.
  const Occlusion way = std::is_same_v<Tracer, NoTracer>
                            ? choose_occlusion(scene, opt, scratch.overdraw_cells)
                            : Occlusion::far_to_near;
  if (opt.visibility == Visibility::painter && way == Occlusion::near_to_far) {
    image.reshape(scene.width, scene.height);  // every pixel is written: no clear
    scratch.coverage.reset(scene.width, scene.height);
    drawing_order(scene, Visibility::painter, scratch, Occlusion::near_to_far);
    OcclusionCanvas<P> canvas(image, scratch.coverage, {0, scene.height});
    RenderStats stats;
    stats.path = Occlusion::near_to_far;
    fill_near_to_far(canvas, scene, scratch.order, scratch.depth, opt, scratch.fill,
                     [&](int, const FillResult& r, long long visible) { stats.count(r, visible); });
    return stats;
  }
  image.reset(scene.width, scene.height, P::from(scene.background));
  if (opt.visibility == Visibility::zbuffer && way == Occlusion::near_to_far)
    return detail::render_zbuffer_near_to_far(image, scene, opt, scratch);
  if (opt.visibility == Visibility::zbuffer) {
    scratch.zbuffer.assign(static_cast<std::size_t>(scene.width) * scene.height,
                           std::numeric_limits<double>::infinity());
    // Only a pixel-level trace reads the per-pixel outcomes of the depth test.
    ZBufferCanvas<P> canvas(image, scratch.zbuffer, {0, scene.height},
                            kTraceHooks && Tracer::max_level >= TraceLevel::pixel);
    return detail::render_into(canvas, scene, Visibility::zbuffer, opt, scratch, tracer);
  }
  ImageCanvas<P> canvas(image);
  return detail::render_into(canvas, scene, Visibility::painter, opt, scratch, tracer);
}

template <class P>
RenderStats render(Image<P>& image, const Scene& scene, const FillOptions& opt,
                   RenderScratch& scratch) {
  NoTracer none;
  return render(image, scene, opt, scratch, none);
}

// The scene on a fresh canvas of its size and background colour, in pixels of type P: Rgb32f is
// the course's float canvas, Bgr8 the 8-bit image that files, videos and OpenCV use.
template <class P = Rgb32f, FillTracer Tracer = NoTracer>
Image<P> render(const Scene& scene, const FillOptions& opt, Tracer& tracer,
                RenderStats* stats = nullptr) {
  Image<P> image;
  RenderScratch scratch;
  const RenderStats s = render(image, scene, opt, scratch, tracer);
  if (stats) *stats = s;
  return image;
}

template <class P = Rgb32f>
Image<P> render(const Scene& scene, const FillOptions& opt = {}, RenderStats* stats = nullptr) {
  NoTracer none;
  return render<P>(scene, opt, none, stats);
}

}  // namespace scantrace
