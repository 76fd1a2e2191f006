#pragma once
// The render on several threads. The image is cut into horizontal bands; each thread takes bands
// in turn and draws, into its band only, every face that reaches it, in the full painter's order
// (or, z-buffered, in scene order through the band's rows of one shared depth buffer). A pixel
// belongs to exactly one band and receives exactly the same sequence of writes (and depth tests)
// as in the single-threaded render, so the result is bit-identical: parallelism changes who draws
// a pixel, never what is drawn on it or in which order.
//
// Why bands and not faces: faces overlap, and the painter's order between overlapping faces is
// the whole point, so splitting the face list would need locks or a merge; bands need neither.
// Why more bands than threads: the faces are rarely spread evenly over the rows (the course scene
// is a figure in the middle of the canvas), so threads pick bands from a shared counter.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <span>
#include <thread>
#include <vector>

#include "painter.hpp"

namespace scantrace {

namespace detail {

// The bands each face may touch: rows floor(y_min) … ceil(y_max) of its vertices. A face can only
// own rows within [ceil(y_min'), floor(y_max')] of its snapped vertices, and snapping moves a
// vertex by at most half a pixel (so ceil(y_min') ≥ floor(y_min)). These are the rows the
// near-to-far render's box test reads too (OcclusionCanvas::begin_face), so every band that lists a
// face holds part of that box. Faces that cannot touch a band are not even set up by that band's
// thread.
inline std::vector<std::vector<int>> faces_by_band(const Scene& scene,
                                                   const std::vector<int>& order, int band_height,
                                                   int bands) {
  std::vector<std::vector<int>> by_band(bands);
  for (int f : order) {
    const auto& face = scene.faces[f];
    double y_min = scene.vertices[face[0]].y, y_max = y_min;
    for (int k = 1; k < 3; ++k) {
      y_min = std::min(y_min, scene.vertices[face[k]].y);
      y_max = std::max(y_max, scene.vertices[face[k]].y);
    }
    // Rows floor(y_min) … ceil(y_max) miss the canvas; also NaN: never filled.
    if (!(y_max > -1.0) || !(y_min < scene.height)) continue;
    // Clamped before converting: a vertex may lie a billion pixels away.
    const double lo = std::max(y_min, 0.0), hi = std::min(y_max, scene.height - 1.0);
    const int first = std::min(static_cast<int>(lo) / band_height, bands - 1);
    const int last = std::min(static_cast<int>(std::ceil(hi)) / band_height, bands - 1);
    for (int b = first; b <= last; ++b) by_band[b].push_back(f);
  }
  return by_band;
}

// What one band saw of a face in the near-to-far render, as bits: a face is counted once, as the
// whole-image render counts it. A band sees only its rows, and a face may be off a band that
// lists it (the lists are conservative) or hidden in one band and seen in another: seen anywhere
// makes it filled; culled, or skipped for a reason of its own (degenerate, too small), is the
// same in every band that sets it up; hidden only counts when no band saw a pixel of it, and it
// was rejected before set-up when no band set it up and found it hidden.
enum NearToFarSeen : char {
  seen_filled = 1,
  seen_culled = 2,
  seen_skipped = 4,    // a reason of the face's own
  seen_clipped = 8,    // set up, every pixel covered
  seen_rejected = 16,  // rejected before set-up
  seen_off_band = 32,  // off the band's rows
};

inline char near_to_far_seen(const FillResult& r, long long visible) {
  switch (r.skipped) {
    case SkipReason::none:  // owning no pixel of the band is not owning none of the image
      return visible > 0 ? seen_filled : r.pixels > 0 ? seen_clipped : seen_off_band;
    case SkipReason::culled:
      return seen_culled;
    case SkipReason::hidden:
      return seen_rejected;
    case SkipReason::offscreen:
      return seen_off_band;
    default:
      return seen_skipped;
  }
}

inline void count_near_to_far(RenderStats& stats, char seen) {
  if (seen & seen_filled) {
    ++stats.triangles_filled;
  } else if (seen & seen_culled) {
    ++stats.triangles_culled;
  } else if (seen & seen_skipped) {
    ++stats.triangles_skipped;
  } else if (seen & (seen_clipped | seen_rejected)) {
    ++stats.triangles_hidden;
    if (!(seen & seen_clipped)) ++stats.triangles_rejected;
  } else {
    ++stats.triangles_skipped;
  }
}

// What the bands' threads found, joined after them. Per face: near to far, the NearToFarSeen
// bits of every band that listed it; otherwise 1 when some band filled part of it, 2 when culled
// (every band that sets it up culls it), 0 otherwise. Per band: the pixels written and those
// clipped. The flags are relaxed atomic stores and or-s (which band sees a face first is up to
// the threads; the join orders them before they are read), and a band's pixels are counted in a
// local and stored once: the threads' counters share a cache line, and a store per face bounced
// it between the cores (the 1200² scene's two-thread speed-up was 1.2-1.36 with it).
struct BandTally {
  std::vector<char> faces;
  std::vector<long long> pixels, clipped;
};

enum class BandPath { near_to_far, zbuffer, painter };

// Band b (rows `rows`) of the render: every face of `faces` (the faces listed for it, in the
// drawing order) drawn into those rows only, tallied into `tally`.
template <class P>
void render_band(Image<P>& image, const Scene& scene, const FillOptions& opt,
                 RenderScratch& scratch, BandPath path, int b, RowBand rows,
                 std::span<const int> faces, FillScratch& fill, BandTally& tally) {
  NoTracer none;
  long long band_pixels = 0, band_clipped = 0;
  const auto count = [&](int f, const FillResult& r) {
    if (r.skipped == SkipReason::none)
      std::atomic_ref<char>(tally.faces[f]).store(1, std::memory_order_relaxed);
    if (r.skipped == SkipReason::culled)
      std::atomic_ref<char>(tally.faces[f]).store(2, std::memory_order_relaxed);
    band_pixels += r.pixels;
  };
  const auto seen = [&](int f, const FillResult& r, long long visible) {
    std::atomic_ref<char>(tally.faces[f]).fetch_or(near_to_far_seen(r, visible),
                                                   std::memory_order_relaxed);
    band_pixels += visible;
    if (r.skipped == SkipReason::none) band_clipped += r.pixels - visible;
  };
  if (path == BandPath::near_to_far) {
    OcclusionCanvas<P> canvas(image, scratch.coverage, rows);
    fill_near_to_far(canvas, scene, faces, scratch.depth, opt, fill, seen);
  } else if (path == BandPath::zbuffer) {
    ZBufferCanvas<P> canvas(image, scratch.zbuffer, rows);
    fill_faces(canvas, scene, faces, scratch.depth, opt, fill, none, count);
  } else {
    BandCanvas<P> canvas(image, rows);
    fill_faces(canvas, scene, faces, scratch.depth, opt, fill, none, count);
  }
  tally.pixels[b] = band_pixels;
  tally.clipped[b] = band_clipped;
}

// The render's statistics from the bands' tally.
inline RenderStats tally_stats(const BandTally& tally, BandPath path) {
  RenderStats stats;
  if (path == BandPath::near_to_far) {
    stats.path = Occlusion::near_to_far;
    for (char f : tally.faces) count_near_to_far(stats, f);
  } else {
    for (char f : tally.faces)
      (f == 1   ? stats.triangles_filled
       : f == 2 ? stats.triangles_culled
                : stats.triangles_skipped) += 1;
  }
  for (long long p : tally.pixels) stats.pixels += p;
  for (long long p : tally.clipped) stats.pixels_clipped += p;
  return stats;
}

}  // namespace detail

// The scene rendered into the caller's `image` (as render(image, scene, opt, scratch) does) with
// `threads` threads (0: one per core); equal, pixel for pixel, to the single-threaded render.
// Statistics count a face as filled when any band filled part of it. `scratch` holds the depths,
// the order and the z-buffer; each thread has a fill scratch of its own.
template <class P>
RenderStats render_parallel(Image<P>& image, const Scene& scene, const FillOptions& opt,
                            int threads, RenderScratch& scratch) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  // The float method accumulates down each edge from the row where its run begins, x and the
  // Gouraud colours alike, and a band begins runs at its own first row: in bands they would differ
  // from one thread's in the last bits (Gouraud colours: 10 pixels of a 300×211 test scene; an
  // edge's x: 1 pixel of the z-buffered render of two such scenes). That method stays on one
  // thread, so that every render here is the single-threaded image.
  if (opt.method == Method::float32) return render(image, scene, opt, scratch);
  // The z-buffer draws in scene order, and a pixel's depth tests then come in that order in its
  // band as in the whole image: the same writes, so the same image, as with the painter's order.
  // Near to far, each band keeps its rows of one coverage mask, and a face meets in a band the
  // coverage of the same nearer faces as in the whole image.
  using detail::BandPath;
  const BandPath path =
      opt.visibility == Visibility::zbuffer ? BandPath::zbuffer
      : choose_occlusion(scene, opt, scratch.overdraw_cells) == Occlusion::near_to_far
          ? BandPath::near_to_far
          : BandPath::painter;
  if (path == BandPath::near_to_far) {
    image.reshape(scene.width, scene.height);
    scratch.coverage.reset(scene.width, scene.height);
  } else {
    image.reset(scene.width, scene.height, P::from(scene.background));
  }
  drawing_order(scene, opt.visibility, scratch,
                path == BandPath::near_to_far ? Occlusion::near_to_far : Occlusion::far_to_near);
  if (path == BandPath::zbuffer)
    scratch.zbuffer.assign(static_cast<std::size_t>(scene.width) * scene.height,
                           std::numeric_limits<double>::infinity());
  // Four bands per thread balance the load; bands of at least 16 rows keep the per-band set-up
  // (and the faces listed in two bands) small.
  const int bands = std::clamp(scene.height / 16, 1, 4 * threads);
  const int band_height = (scene.height + bands - 1) / bands;
  const std::vector<std::vector<int>> by_band =
      detail::faces_by_band(scene, scratch.order, band_height, bands);
  detail::BandTally tally{std::vector<char>(scene.faces.size(), 0),
                          std::vector<long long>(bands, 0), std::vector<long long>(bands, 0)};
  std::atomic<int> next_band{0};
  const auto work = [&] {
    FillScratch fill;  // each thread its own
    for (int b; (b = next_band.fetch_add(1)) < bands;) {
      const RowBand rows{b * band_height, std::min(scene.height, (b + 1) * band_height)};
      detail::render_band(image, scene, opt, scratch, path, b, rows, by_band[b], fill, tally);
    }
  };
  {
    std::vector<std::jthread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
  }
  return detail::tally_stats(tally, path);
}

// The same on a fresh image of the scene's size.
template <class P = Rgb32f>
Image<P> render_parallel(const Scene& scene, const FillOptions& opt, int threads = 0,
                         RenderStats* stats = nullptr) {
  Image<P> image;
  RenderScratch scratch;
  const RenderStats s = render_parallel(image, scene, opt, threads, scratch);
  if (stats) *stats = s;
  return image;
}

}  // namespace scantrace
