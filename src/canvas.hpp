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
#include "flat_span.hpp"
#include "image.hpp"
#include "shade_bytes.hpp"
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
// box (occlusion_canvas.hpp, zbuffer_canvas.hpp). Empty also for NaN vertices; a vertex far off
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

// Pixels [x_begin, x_end) of `row` in the colours c, c + step, c + 2·step, … (a Gouraud span of
// the exact method, linear from its first pixel): 8-bit pixels in fixed point (shade_bytes),
// others converted pixel by pixel.
template <class P>
void shade_pixels(P* row, int x_begin, int x_end, Color c, Color step) {
  if constexpr (std::is_same_v<P, Bgr8>) {
    shade_bytes(row + x_begin, x_end - x_begin, c, step);
  } else {
    for (int x = x_begin; x < x_end; ++x, c += step) row[x] = P::from(c);
  }
}

// A span of shade_pixels written in parts, in increasing order: pixels [a, b) of the span
// [x_begin, x_end), each with the same bits shade_pixels gives it. A span partly hidden by nearer
// faces (occlusion_canvas.hpp) writes only its visible runs; the colour is still the one of the
// whole span at that pixel, or the image would depend on what was hidden.
template <class P>
class ShadedSpan {
 public:
  ShadedSpan(int x_begin, int /*x_end*/, Color c, Color step) : x_(x_begin), c_(c), step_(step) {}
  // Inlined, and the colour stepped in locals: this object is the claim's (its address is
  // taken), so stepping the members stored and reloaded the colour every pixel, and once the
  // sweep had grown GCC called this instead (5% of the course scene's Gouraud render, perf).
  [[gnu::always_inline]] void write(P* row, int a, int b) {
    // shade_pixels adds the step once per pixel; skipped pixels take the same additions, since
    // c + k·step rounds differently from k additions.
    Color c = c_;
    const Color step = step_;
    int x = x_;
    for (; x < a; ++x) c += step;
    for (; x < b; ++x, c += step) row[x] = P::from(c);
    c_ = c, x_ = x;
  }

 private:
  int x_;
  Color c_, step_;
};

template <>
class ShadedSpan<Bgr8> {
 public:
  // The ramps of the whole span, begun later for each part: pixel k of the span is the same
  // integer expression whichever part draws it.
  ShadedSpan(int x_begin, int x_end, Color c, Color step)
      : x_begin_(x_begin), ramps_(x_end - x_begin, c, step) {}
  void write(Bgr8* row, int a, int b) { shade_ramps(row + a, b - a, ramps_.skip(a - x_begin_)); }

 private:
  int x_begin_;
  ByteRamps ramps_;
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
