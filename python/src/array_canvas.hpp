#pragma once
// A canvas over memory the binding does not own: a C-contiguous numpy array of shape (M, N, 3),
// float32 or float64. The fill writes the caller's array directly (f_shading fills `img` in place,
// render() fills the array it returns), so no image is copied on the way in or out.
#include <cstddef>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "src/canvas.hpp"
#include "src/fast/shaded_span.hpp"
#include "src/image.hpp"

namespace scantrace::python {

// A float64 pixel holding exactly the values of the C++ float canvas (Rgb32f), widened: a
// colour is rounded to float first. Why: the course's arrays are float64, and a Python render
// must equal the C++ render value for value; full double precision would differ from it in the
// 8th digit (and could round differently to 8 bits at .5 ties).
struct Rgb64 {
  double r = 0, g = 0, b = 0;
  static Rgb64 from(Color c) {
    return {static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b)};
  }
};
static_assert(sizeof(Rgb64) == 3 * sizeof(double));
static_assert(sizeof(Rgb32f) == 3 * sizeof(float));

// The colours of a Gouraud span of a float64 row: c, c + step, c + 2 step, … (`step` added once
// per pixel, never c + k step), each rounded to float and widened as Rgb64::from: what the generic
// loop of canvas.hpp's shade_pixels writes, bit for bit (the same IEEE additions and roundings),
// with red and green as the two lanes of one SSE2 register. perf put the course scene's Gouraud
// render_img 20-30% behind the float32 render, most of it in that loop's three scalar round trips
// per pixel. The colour lives in registers from construction on: it is loaded component by
// component (8-byte loads), since a 16-byte load of a colour just stored as three doubles cannot
// be forwarded from those stores and stalled (perf: 80% of a first version's samples on it).
class WideShade {
 public:
  WideShade(const Color& c, const Color& step)
#if defined(__SSE2__)
      : rg_(_mm_loadh_pd(_mm_load_sd(&c.r), &c.g)),
        step_rg_(_mm_loadh_pd(_mm_load_sd(&step.r), &step.g)),
#else
      : r_(c.r),
        g_(c.g),
        step_r_(step.r),
        step_g_(step.g),
#endif
        b_(c.b),
        step_b_(step.b) {
  }
  // The next n pixels skipped: their additions made, nothing written.
  void skip(int n) {
    for (int i = 0; i < n; ++i) add();
  }
  // The next n pixels written to p[0 .. n).
  void write(Rgb64* p, int n) {
    for (int i = 0; i < n; ++i) {
#if defined(__SSE2__)
      _mm_storeu_pd(&p[i].r, _mm_cvtps_pd(_mm_cvtpd_ps(rg_)));
#else
      p[i].r = static_cast<float>(r_);
      p[i].g = static_cast<float>(g_);
#endif
      p[i].b = static_cast<float>(b_);
      add();
    }
  }

 private:
  void add() {
#if defined(__SSE2__)
    rg_ = _mm_add_pd(rg_, step_rg_);
#else
    r_ += step_r_, g_ += step_g_;
#endif
    b_ += step_b_;
  }
#if defined(__SSE2__)
  __m128d rg_, step_rg_;
#else
  double r_, g_, step_r_, step_g_;
#endif
  double b_, step_b_;
};

// Found by argument-dependent lookup from the fill (scanline_fill.hpp calls shade_pixels on the
// canvas's row), in place of canvas.hpp's template.
inline void shade_pixels(Rgb64* row, int x_begin, int x_end, Color c, Color step) {
  WideShade(c, step).write(row + x_begin, x_end - x_begin);
}

// The same interface and the same arithmetic as ImageCanvas<P> (src/canvas.hpp), so that the
// fill takes the same path and writes the same values as into an Image<P>.
template <class P>
class ArrayCanvas {
 public:
  using Pixel = P;
  ArrayCanvas(P* pixels, int width, int height) : pixels_(pixels), width_(width), height_(height) {}
  int width() const { return width_; }
  int height() const { return height_; }
  P* row(int y) { return pixels_ + static_cast<std::size_t>(y) * width_; }
  std::ptrdiff_t row_stride() const { return width_; }
  static P convert(Color c) { return P::from(c); }
  void fill_span(int y, int x_begin, int x_end, Color c) {
    scantrace::fill_pixels(row(y) + x_begin, row(y) + x_end, convert(c));
  }
  void set(int x, int y, Color c) { row(y)[x] = convert(c); }
  // Every pixel set to `c` (the background before a render).
  void clear(Color c) {
    const std::size_t n = static_cast<std::size_t>(width_) * height_;
    if (n > 0) scantrace::fill_pixels(pixels_, pixels_ + n, convert(c));
  }

 private:
  P* pixels_;
  int width_, height_;
};

}  // namespace scantrace::python

namespace scantrace {

// A partly hidden Gouraud span of a float64 row (the near-to-far render, occlusion_canvas.hpp),
// written in its visible runs by WideShade: each pixel gets the bits ShadedSpan<P> gives it.
template <>
class ShadedSpan<python::Rgb64> {
 public:
  ShadedSpan(int x_begin, int /*x_end*/, Color c, Color step) : x_(x_begin), shade_(c, step) {}
  // Runs come in increasing order (CoverageMask::claim); the pixels between them are skipped
  // with their additions, as the generic span does. The colour is stepped in a local copy, kept
  // in registers: this object is the claim's (its address is taken), and stepping the member
  // stored and reloaded the colour on every pixel (perf: the loop's samples on those loads).
  [[gnu::always_inline]] void write(python::Rgb64* row, int a, int b) {
    python::WideShade shade = shade_;
    shade.skip(a - x_);
    shade.write(row + a, b - a);
    shade_ = shade;
    x_ = b;
  }

 private:
  int x_;
  python::WideShade shade_;
};

}  // namespace scantrace
