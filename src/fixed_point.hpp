#pragma once
// The subpixel grid. Coverage is decided on vertices snapped to multiples of 1/2^bits pixel, in
// integer arithmetic, so that no pixel's fate depends on floating-point rounding: two triangles
// sharing an edge see bit-identical edge coordinates and compute the same exact intersections.
//
// Ranges: |coordinate| <= kMaxCoordinate pixels (just above 1e9, so vertices a billion pixels off
// the canvas still work) and bits <= kMaxSubpixelBits. Then a snapped coordinate needs < 2^43,
// a difference < 2^44, the stepping increment dx·2^bits < 2^56 (int64), and the products formed
// when starting an edge at a row or comparing two edges < 2^100 (__int128).
#include <cmath>
#include <cstdint>

#include "vec2.hpp"

namespace scantrace {

using i64 = std::int64_t;
__extension__ using i128 = __int128;

inline constexpr double kMaxCoordinate = 1073741824.0;  // 2^30 px
inline constexpr int kMaxSubpixelBits = 12;
inline constexpr int kDefaultSubpixelBits = 8;

// A point on the subpixel grid, in units of 1/2^bits pixel.
struct FixedPoint {
  i64 x = 0, y = 0;
  friend constexpr bool operator==(FixedPoint, FixedPoint) = default;
};

// floor(a / b) for b > 0. The quotient must fit in 64 bits. A 128-bit division is a library call
// costing tens of cycles, and the numerator usually fits in 64 bits (coordinates within a few
// million pixels), so that case takes the hardware division.
inline constexpr i64 floor_div(i128 a, i64 b) {
  if (a >= INT64_MIN && a <= INT64_MAX) {
    const i64 n = static_cast<i64>(a);
    const i64 q = n / b;
    return (n % b) < 0 ? q - 1 : q;
  }
  i128 q = a / b;
  if ((a % b) < 0) --q;
  return static_cast<i64>(q);
}

class SubpixelGrid {
 public:
  explicit constexpr SubpixelGrid(int bits = kDefaultSubpixelBits) : bits_(bits) {}

  constexpr int bits() const { return bits_; }
  constexpr i64 scale() const { return i64{1} << bits_; }
  constexpr bool valid() const { return bits_ >= 0 && bits_ <= kMaxSubpixelBits; }

  // True when p is finite and inside the supported coordinate range. One comparison a coordinate
  // is both tests: a NaN compares false, and an infinity is beyond the range.
  static bool representable(Vec2 p) {
    return std::fabs(p.x) <= kMaxCoordinate && std::fabs(p.y) <= kMaxCoordinate;
  }

  // Round to the nearest grid point, ties upward (floor(v + 1/2)). Unlike rounding ties away from
  // zero this commutes with translation by whole pixels, which docs/design.md §3 requires.
  FixedPoint snap(Vec2 p) const {
    const double s = static_cast<double>(scale());
    return {round_half_up(p.x * s), round_half_up(p.y * s)};
  }

  // floor(v + 1/2) without evaluating v + 1/2, which rounds the largest double below 0.5 up to
  // 1.0. v·2^bits is exact (a power-of-two scale) and so is v − floor(v), so the tie test is exact.
  // floor is taken as truncation corrected for negative non-integers: |v| < 2^43 here, so the
  // conversions are exact, and baseline x86-64 has no floor instruction (std::floor is a call).
  static i64 round_half_up(double v) {
    i64 f = static_cast<i64>(v);
    if (static_cast<double>(f) > v) --f;
    return f + (v - static_cast<double>(f) >= 0.5 ? 1 : 0);
  }

  Vec2 to_pixels(FixedPoint p) const {
    const double s = static_cast<double>(scale());
    return {static_cast<double>(p.x) / s, static_cast<double>(p.y) / s};
  }

  // The smallest row/column index whose pixel centre is at or after v (grid units): ceil(v /
  // 2^bits). Since C++20 >> of a negative value is an arithmetic shift, i.e. exactly floor(v /
  // 2^bits).
  constexpr i64 ceil_to_pixel(i64 v) const { return -((-v) >> bits_); }
  // The largest index whose centre is at or before v: floor(v / 2^bits).
  constexpr i64 floor_to_pixel(i64 v) const { return v >> bits_; }

 private:
  int bits_;
};

}  // namespace scantrace
