#pragma once
// What the fill writes to. Image<P> is the usual canvas; tests use canvases that count how often
// each pixel is written, which is how watertightness is checked on the real fill.
#include <algorithm>
#include <concepts>

#include "color.hpp"
#include "image.hpp"

namespace scantrace {

template <class C>
concept Canvas = requires(C& c, int x, int y, Color col) {
  { c.width() } -> std::convertible_to<int>;
  { c.height() } -> std::convertible_to<int>;
  c.fill_span(y, x, x, col);  // pixels [x_begin, x_end) of row y, one colour
  c.set(x, y, col);           // one pixel
};

// Adapts an Image<P> whose pixel type converts from Color (P::from).
template <class P>
class ImageCanvas {
 public:
  explicit ImageCanvas(Image<P>& image) : image_(image) {}
  int width() const { return image_.width(); }
  int height() const { return image_.height(); }
  void fill_span(int y, int x_begin, int x_end, Color c) {
    P* row = image_.row(y);
    std::fill(row + x_begin, row + x_end, P::from(c));
  }
  void set(int x, int y, Color c) { image_.row(y)[x] = P::from(c); }

 private:
  Image<P>& image_;
};

}  // namespace scantrace
