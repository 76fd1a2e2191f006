#pragma once
// What the fill writes to. Image<P> is the usual canvas; tests use canvases that count how often
// each pixel is written, which is how watertightness is checked on the real fill.
#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>

#include "color.hpp"
#include "fast/flat_span.hpp"
#include "image.hpp"
#include "vec2.hpp"

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

// The pixels a face can own, columns x0 … x1 and rows y0 … y1 (empty when x0 > x1 or y0 > y1),
// from its vertices before snapping, clipped to columns [0, width) and to `band`. Snapping moves a
// vertex by at most half a pixel, to a point that rounds into floor(v) … ceil(v), so columns
// floor(x_min) … ceil(x_max) and rows floor(y_min) … ceil(y_max) hold every pixel centre the face
// owns under either fill rule. The renders that reject hidden faces before their set-up test this
// box (fast/occlusion_canvas.hpp, zbuffer_canvas.hpp). Empty also for NaN vertices; a vertex far off
// the canvas is clamped before it is converted to an int.
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  bool empty() const { return x0 > x1 || y0 > y1; }
};

inline PixelBox face_pixels(std::span<const Vec2> v, int width, RowBand band) {
  const double x_min = std::min({v[0].x, v[1].x, v[2].x}),
               x_max = std::max({v[0].x, v[1].x, v[2].x});
  const double y_min = std::min({v[0].y, v[1].y, v[2].y}),
               y_max = std::max({v[0].y, v[1].y, v[2].y});
  if (!(x_max > -1.0 && x_min < width && y_max > band.begin - 1.0 && y_min < band.end)) return {};
  // floor and ceil by truncation (std::floor is a call on baseline x86-64): the lower ends are
  // clamped to ≥ 0 and the upper ones lie above −1, where truncating is rounding toward zero.
  const auto ceil = [](double x) {
    const int t = static_cast<int>(x);
    return t + (static_cast<double>(t) < x);
  };
  return {static_cast<int>(std::max(x_min, 0.0)),
          static_cast<int>(std::max(y_min, double(band.begin))), ceil(std::min(x_max, width - 1.0)),
          ceil(std::min(y_max, band.end - 1.0))};
}

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
  { c.row_stride() } -> std::same_as<std::ptrdiff_t>;  // row(y + 1) − row(y), in pixels
};

// A DirectCanvas's pixel type; int for other canvases (a placeholder the fill never writes).
template <class C>
struct DirectPixelOf {
  using type = int;
};
template <DirectCanvas C>
struct DirectPixelOf<C> {
  using type = typename C::Pixel;
};
template <class C>
using DirectPixel = typename DirectPixelOf<C>::type;

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
  std::ptrdiff_t row_stride() const { return image_.width(); }

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
