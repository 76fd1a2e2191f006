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
    // A flat polygon fills every row with the same colour: convert it once, not once per row.
    if (!(c == last_color_)) last_color_ = c, last_pixel_ = P::from(c);
    P* row = image_.row(y);
    std::fill(row + x_begin, row + x_end, last_pixel_);
  }
  void set(int x, int y, Color c) { image_.row(y)[x] = P::from(c); }

 private:
  Image<P>& image_;
  Color last_color_{-1, -1, -1};  // never a valid colour, so the first span converts
  P last_pixel_ = P::from(last_color_);
};

}  // namespace scantrace
