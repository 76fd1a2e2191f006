#pragma once
// What the fill writes to. Image<P> is the usual canvas; tests use canvases that count how often
// each pixel is written, which is how watertightness is checked on the real fill.
#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstring>

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

// The rows [begin, end) a canvas accepts. A canvas may be a horizontal band of a larger image
// (band_render.hpp): it then has `rows()`, and the fill neither visits nor writes rows outside it,
// exactly as it treats rows outside an ordinary canvas.
struct RowBand {
  int begin = 0, end = 0;
};

template <Canvas C>
RowBand canvas_rows(const C& canvas) {
  if constexpr (requires {
                  { canvas.rows() } -> std::same_as<RowBand>;
                })
    return canvas.rows();
  else
    return {0, canvas.height()};
}

// A canvas whose rows are plain pixel arrays. The fill then converts a flat colour once per
// polygon, not once per span, and writes pixels through a row pointer held in a register.
template <class C>
concept DirectCanvas = Canvas<C> && requires(C& c, int y, Color col) {
  typename C::Pixel;
  { C::convert(col) } -> std::same_as<typename C::Pixel>;
  { c.row(y) } -> std::same_as<typename C::Pixel*>;
};

// Adapts an Image<P> whose pixel type converts from Color (P::from).
template <class P>
class ImageCanvas {
 public:
  using Pixel = P;

  explicit ImageCanvas(Image<P>& image) : image_(image) {}
  int width() const { return image_.width(); }
  int height() const { return image_.height(); }
  void fill_span(int y, int x_begin, int x_end, Color c) {
    fill_pixels(row(y) + x_begin, row(y) + x_end, convert(c));
  }
  void set(int x, int y, Color c) { row(y)[x] = convert(c); }

  static P convert(Color c) { return P::from(c); }
  P* row(int y) { return image_.row(y); }

  // The value is a local copy on purpose: std::fill reads it through a reference, and with 8-bit
  // pixels every byte stored may alias it, so it would be reloaded for every pixel. Long spans
  // are written as a few pixels copied onto the rest in doubling blocks: memcpy moves a 3-byte
  // pattern as fast as memset moves a 1-byte one, a pixel loop does not.
  static void fill_pixels(P* first, P* last, P value) {
    constexpr std::ptrdiff_t kShort = 32;
    if (last - first <= kShort) {
      for (; first != last; ++first) *first = value;
      return;
    }
    for (P* p = first; p != first + kShort; ++p) *p = value;
    for (std::ptrdiff_t done = kShort, n = last - first; done < n;) {
      const std::ptrdiff_t chunk = std::min(done, n - done);
      std::memcpy(first + done, first, static_cast<std::size_t>(chunk) * sizeof(P));
      done += chunk;
    }
  }

 private:
  Image<P>& image_;
};

// The rows [band.begin, band.end) of an image, as a canvas of the image's full size: coordinates
// are unchanged (no translation of the vertices, which would not be exact), and the fill clips to
// the band as it clips to the canvas.
template <class P>
class BandCanvas : public ImageCanvas<P> {
 public:
  BandCanvas(Image<P>& image, RowBand band) : ImageCanvas<P>(image), band_(band) {}
  RowBand rows() const { return band_; }

 private:
  RowBand band_;
};

}  // namespace scantrace
