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
#include <thread>
#include <vector>

#include "painter.hpp"

namespace scantrace {

namespace detail {

// The bands each face may touch, from its vertices' rows widened by one pixel on each side: a
// face can only own rows within [ceil(y_min), floor(y_max)] of its snapped vertices, and
// snapping moves a vertex by less than a pixel. Faces that cannot touch a band are not even set
// up by that band's thread.
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
    if (!(y_max >= -1.0) || !(y_min <= scene.height + 1.0)) continue;  // also NaN: never filled
    // Clamped before converting: a vertex may lie a billion pixels away.
    const double lo = std::max(y_min - 1.0, 0.0), hi = std::min(y_max + 1.0, scene.height - 1.0);
    const int first = std::min(static_cast<int>(lo) / band_height, bands - 1);
    const int last = std::min(static_cast<int>(std::ceil(hi)) / band_height, bands - 1);
    for (int b = first; b <= last; ++b) by_band[b].push_back(f);
  }
  return by_band;
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
  image.reset(scene.width, scene.height, P::from(scene.background));
  // The z-buffer draws in scene order, and a pixel's depth tests then come in that order in its
  // band as in the whole image: the same writes, so the same image, as with the painter's order.
  const bool zbuffer = opt.visibility == Visibility::zbuffer;
  drawing_order(scene, opt.visibility, scratch);
  if (zbuffer)
    scratch.zbuffer.assign(static_cast<std::size_t>(scene.width) * scene.height,
                           std::numeric_limits<double>::infinity());
  const std::vector<double>& depth = scratch.depth;
  const std::vector<int>& order = scratch.order;
  // Four bands per thread balance the load; bands of at least 16 rows keep the per-band set-up
  // (and the faces listed in two bands) small.
  const int bands = std::clamp(scene.height / 16, 1, 4 * threads);
  const int band_height = (scene.height + bands - 1) / bands;
  const std::vector<std::vector<int>> by_band =
      detail::faces_by_band(scene, order, band_height, bands);

  // Per face: 1 when some band filled part of it, 2 when culled (every band that sets it up culls
  // it), 0 otherwise. Bands only ever store these values, so concurrent stores agree.
  std::vector<char> filled(scene.faces.size(), 0);
  std::vector<long long> pixels(bands, 0);
  std::atomic<int> next_band{0};
  const auto work = [&] {
    FillScratch fill;  // each thread its own
    NoTracer none;
    for (int b; (b = next_band.fetch_add(1)) < bands;) {
      const RowBand rows{b * band_height, std::min(scene.height, (b + 1) * band_height)};
      // Counted in a local and stored once per band: the threads' counters share a cache line,
      // and a store per face bounced it between the cores (the 1200² scene's two-thread
      // speed-up was 1.2-1.36 with it). The flags are relaxed stores for the same reason: the
      // join orders them before they are read.
      long long band_pixels = 0;
      const auto count = [&](int f, const FillResult& r) {
        if (r.skipped == SkipReason::none)
          std::atomic_ref<char>(filled[f]).store(1, std::memory_order_relaxed);
        if (r.skipped == SkipReason::culled)
          std::atomic_ref<char>(filled[f]).store(2, std::memory_order_relaxed);
        band_pixels += r.pixels;
      };
      if (zbuffer) {
        ZBufferCanvas<P> canvas(image, scratch.zbuffer, rows);
        fill_faces(canvas, scene, by_band[b], depth, opt, fill, none, count);
      } else {
        BandCanvas<P> canvas(image, rows);
        fill_faces(canvas, scene, by_band[b], depth, opt, fill, none, count);
      }
      pixels[b] = band_pixels;
    }
  };
  {
    std::vector<std::jthread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
  }
  RenderStats stats;
  for (char f : filled)
    (f == 1   ? stats.triangles_filled
     : f == 2 ? stats.triangles_culled
              : stats.triangles_skipped) += 1;
  for (long long p : pixels) stats.pixels += p;
  return stats;
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
