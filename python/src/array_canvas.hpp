#pragma once
// A canvas over memory the binding does not own: a C-contiguous numpy array of shape (M, N, 3),
// float32 or float64. The fill writes the caller's array directly (f_shading fills `img` in place,
// render() fills the array it returns), so no image is copied on the way in or out.
#include <cstddef>

#include "src/canvas.hpp"
#include "src/image.hpp"

namespace scantrace::python {

// A float64 pixel holding exactly the values of the C++ float canvas (Rgb32f), widened: a
// colour is rounded to float first. Why: the course's arrays are float64, and the issue asks that
// a Python render equal the C++ render value for value; full double precision would differ from
// it in the 8th digit (and could round differently to 8 bits at .5 ties).
struct Rgb64 {
  double r = 0, g = 0, b = 0;
  static Rgb64 from(Color c) {
    return {static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b)};
  }
};
static_assert(sizeof(Rgb64) == 3 * sizeof(double));
static_assert(sizeof(Rgb32f) == 3 * sizeof(float));

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
