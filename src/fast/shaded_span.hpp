#pragma once
// Writing the exact method's Gouraud span in a canvas's pixel format: its colour is linear from
// the first pixel (c, c + step, c + 2·step, …), so a span is written without a colour per pixel
// from the edges. 8-bit pixels take fixed point in SIMD lanes (shade_bytes.hpp).
#include <type_traits>

#include "shade_bytes.hpp"
#include "src/color.hpp"
#include "src/image.hpp"

namespace scantrace {

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
// faces (fast/occlusion_canvas.hpp) writes only its visible runs; the colour is still the one of the
// whole span at that pixel, or the image would depend on what was hidden.
template <class P>
class ShadedSpan {
 public:
  ShadedSpan(int x_begin, int /*x_end*/, Color c, Color step) : x_(x_begin), c_(c), step_(step) {}
  // Inlined, and the colour stepped in locals: this object is the claim's (its address is
  // taken), so stepping the members would store and reload the colour every pixel.
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

}  // namespace scantrace
