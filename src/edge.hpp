#pragma once
// One non-horizontal edge of the edge table, and its exact intersection with successive scanlines.
//
// The textbook active-edge loop keeps x as a float and adds 1/m per row; after a few hundred rows
// the sum has drifted and shared edges of neighbouring triangles disagree about a pixel. Here x is
// kept as an exact rational q + r/den (pixels), den = 2^bits · dy, 0 <= r < den: moving one row
// down adds the constant dx·2^bits / den, done with an integer quotient and remainder, so the value
// at every row is exactly the value the edge equation gives (Bresenham's idea, in fixed point).
#include <compare>

#include "fixed_point.hpp"

namespace scantrace {

struct Edge {
  int id = 0;      // the edge from polygon vertex id to vertex (id + 1) mod n
  int top = 0;     // index of the upper endpoint (smaller y)
  int bottom = 0;  // index of the lower endpoint
  FixedPoint p_top, p_bottom;
  i64 first_row = 0;  // first scanline this edge is active on
  i64 last_row = -1;  // last scanline (first_row > last_row: the edge crosses no scanline)

  // Exact intersection with the current row: x = q + r / den pixels.
  i64 q = 0, r = 0, den = 1;
  i64 step_q = 0, step_r = 0;

  i64 dx() const { return p_bottom.x - p_top.x; }
  i64 dy() const { return p_bottom.y - p_top.y; }

  // Position the intersection at scanline `row` (any row, also far from the vertices: this is how
  // rows above the canvas are skipped without being iterated).
  void start_at(i64 row, i64 scale) {
    den = scale * dy();
    const i128 num =
        static_cast<i128>(p_top.x) * dy() + static_cast<i128>(dx()) * (row * scale - p_top.y);
    q = floor_div(num, den);
    r = static_cast<i64>(num - static_cast<i128>(q) * den);
    const i64 inc = dx() * scale;
    step_q = floor_div(inc, den);
    step_r = inc - step_q * den;
  }

  void advance() {
    q += step_q;
    r += step_r;
    if (r >= den) {
      ++q;
      r -= den;
    }
  }

  i64 ceil_x() const { return q + (r != 0); }
  i64 floor_x() const { return q; }
  double x() const {
    return static_cast<double>(q) + static_cast<double>(r) / static_cast<double>(den);
  }
};

// Exact order of two edges on the current row: by x, then (where they meet) by slope dx/dy, so
// that two edges leaving a common top vertex are ordered as they are just below it.
inline std::strong_ordering compare_on_row(const Edge& a, const Edge& b) {
  if (a.q != b.q) return a.q <=> b.q;
  const i128 ra = static_cast<i128>(a.r) * b.den, rb = static_cast<i128>(b.r) * a.den;
  if (ra != rb) return ra <=> rb;
  return static_cast<i128>(a.dx()) * b.dy() <=> static_cast<i128>(b.dx()) * a.dy();
}

}  // namespace scantrace
