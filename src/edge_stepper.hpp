#pragma once
// Following an edge's intersection with the scanlines, three ways. The sweep (scanline_sweep.hpp)
// is the same for all of them; only this arithmetic differs, which is what makes the methods
// comparable (docs/accuracy.md).
//
//   ExactStepper   x = q + r/den exactly, stepped with an integer quotient and remainder
//                  (Bresenham's idea in fixed point): every row gets the value the edge equation
//                  gives, so neighbouring triangles agree on every shared-edge pixel.
//   FloatStepper   the textbook loop: x += 1/m in float32, and the edge colour += Δc per row.
//                  The sum drifts; after a few hundred rows a shared edge's pixel can change hands.
//   DoubleStepper  x recomputed from the edge equation in double on every row: no drift, but an
//                  intersection that is exactly on a pixel centre can land an ulp either side.
#include <array>
#include <cmath>
#include <compare>
#include <span>

#include "color.hpp"
#include "edge.hpp"
#include "vector_interp.hpp"

namespace scantrace {

// The colour where `e` crosses row y: the course's vector_interp along y, from the upper endpoint
// to the lower one (a fixed direction, so both triangles sharing the edge get the same value).
inline Color edge_color_at(const Edge& e, i64 y, std::span<const Color> colors,
                           const SubpixelGrid& grid) {
  return vector_interp(grid.to_pixels(e.p_top), grid.to_pixels(e.p_bottom), colors[e.top],
                       colors[e.bottom], static_cast<double>(y), Axis::y);
}

struct ExactStepper {
  i64 q = 0, r = 0, den = 1;
  i64 step_q = 0, step_r = 0;

  // Position the intersection at scanline `row` (any row, also far from the vertices: this is how
  // rows above the canvas are skipped without being iterated).
  void start(const Edge& e, i64 row, const SubpixelGrid& grid, std::span<const Color>) {
    const i64 scale = grid.scale();
    den = scale * e.dy();
    const i128 num = static_cast<i128>(e.p_top.x) * e.dy() +
                     static_cast<i128>(e.dx()) * (row * scale - e.p_top.y);
    q = floor_div(num, den);
    r = static_cast<i64>(num - static_cast<i128>(q) * den);
    const i64 inc = e.dx() * scale;
    step_q = floor_div(inc, den);
    step_r = inc - step_q * den;
  }
  // Branch-free: whether the remainder carries depends on the slope's fraction, so for most
  // edges it alternates irregularly, and a mispredicted branch costs more than a whole step.
  void advance() {
    r += step_r;
    const bool carry = r >= den;
    q += step_q + carry;
    r -= carry ? den : 0;
  }
  i64 ceil_x() const { return q + (r != 0); }
  i64 floor_x() const { return q; }
  double x() const {
    return static_cast<double>(q) + static_cast<double>(r) / static_cast<double>(den);
  }
  Color color(const Edge& e, i64 y, std::span<const Color> c, const SubpixelGrid& g) const {
    return edge_color_at(e, y, c, g);
  }
  // Exact order on the current row.
  std::strong_ordering operator<=>(const ExactStepper& o) const {
    if (q != o.q) return q <=> o.q;
    return static_cast<i128>(r) * o.den <=> static_cast<i128>(o.r) * den;
  }
};

struct DoubleStepper {
  double x_top = 0, y_top = 0, slope = 0, y = 0;

  void start(const Edge& e, i64 row, const SubpixelGrid& grid, std::span<const Color>) {
    const Vec2 top = grid.to_pixels(e.p_top);
    x_top = top.x;
    y_top = top.y;
    slope = static_cast<double>(e.dx()) / static_cast<double>(e.dy());
    y = static_cast<double>(row);
  }
  void advance() { y += 1.0; }
  double x() const { return x_top + (y - y_top) * slope; }
  i64 ceil_x() const { return static_cast<i64>(std::ceil(x())); }
  i64 floor_x() const { return static_cast<i64>(std::floor(x())); }
  Color color(const Edge& e, i64 row, std::span<const Color> c, const SubpixelGrid& g) const {
    return edge_color_at(e, row, c, g);
  }
  std::partial_ordering operator<=>(const DoubleStepper& o) const { return x() <=> o.x(); }
};

struct FloatStepper {
  float xf = 0, dx = 0;
  std::array<float, 3> c{}, dc{};

  void start(const Edge& e, i64 row, const SubpixelGrid& grid, std::span<const Color> colors) {
    const Vec2 top = grid.to_pixels(e.p_top), bottom = grid.to_pixels(e.p_bottom);
    const float dy = static_cast<float>(bottom.y - top.y);
    dx = static_cast<float>(bottom.x - top.x) / dy;  // 1/m, the textbook's increment
    const float from_top = static_cast<float>(row) - static_cast<float>(top.y);
    xf = static_cast<float>(top.x) + from_top * dx;
    const Color ct = colors[e.top], cb = colors[e.bottom];
    const std::array<double, 3> a{ct.r, ct.g, ct.b}, b{cb.r, cb.g, cb.b};
    for (int k = 0; k < 3; ++k) {
      dc[k] = static_cast<float>(b[k] - a[k]) / dy;
      c[k] = static_cast<float>(a[k]) + from_top * dc[k];
    }
  }
  void advance() {
    xf += dx;
    for (int k = 0; k < 3; ++k) c[k] += dc[k];
  }
  double x() const { return xf; }
  i64 ceil_x() const { return static_cast<i64>(std::ceil(xf)); }
  i64 floor_x() const { return static_cast<i64>(std::floor(xf)); }
  Color color(const Edge&, i64, std::span<const Color>, const SubpixelGrid&) const {
    return {c[0], c[1], c[2]};
  }
  std::partial_ordering operator<=>(const FloatStepper& o) const { return xf <=> o.xf; }
};

}  // namespace scantrace
