#pragma once
// One non-horizontal edge of the edge table: its endpoints on the subpixel grid, oriented top to
// bottom, and the scanlines it is active on. How x is followed from row to row is the stepper's
// business (edge_stepper.hpp); the edge table and the sweep are the same for every method.
#include <compare>

#include "fill_options.hpp"
#include "fixed_point.hpp"

namespace scantrace {

struct Edge {
  int id = 0;      // the edge from polygon vertex id to the next vertex of its contour
  int top = 0;     // index of the upper endpoint (smaller y)
  int bottom = 0;  // index of the lower endpoint
  FixedPoint p_top, p_bottom;
  i64 first_row = 0;  // first scanline this edge is active on
  i64 last_row = -1;  // last scanline (first_row > last_row: the edge crosses no scanline)

  i64 dx() const { return p_bottom.x - p_top.x; }
  i64 dy() const { return p_bottom.y - p_top.y; }
  // +1 when the edge runs down (from its vertex `id` at the top), -1 when it runs up: its
  // contribution to the winding number of the points to its right (winding_fill.hpp).
  int winding() const { return top == id ? 1 : -1; }
};

// The edge `id` from vertex i to vertex j of `points` (p[i].y != p[j].y), oriented top to bottom,
// with the rows it owns under `rule`. Half-open in y under the top-left rule: an edge owns the rows
// whose centre lies in [y_top, y_bottom). A vertex shared by two edges of a chain (or of a
// contour, where it turns or passes through) then belongs to exactly one of them, so the active
// list holds exactly two edges per row of a convex polygon.
inline Edge edge_between(const FixedPoint* points, int i, int j, int id, const SubpixelGrid& grid,
                         FillRule rule) {
  Edge e;
  e.id = id;
  e.top = points[i].y < points[j].y ? i : j;
  e.bottom = points[i].y < points[j].y ? j : i;
  e.p_top = points[e.top];
  e.p_bottom = points[e.bottom];
  e.first_row = grid.ceil_to_pixel(e.p_top.y);
  e.last_row = rule == FillRule::top_left ? grid.ceil_to_pixel(e.p_bottom.y) - 1
                                          : grid.floor_to_pixel(e.p_bottom.y);
  return e;
}

// Exact order of two edges' slopes dx/dy (dy > 0 for both).
inline std::strong_ordering compare_slopes(const Edge& a, const Edge& b) {
  return static_cast<i128>(a.dx()) * b.dy() <=> static_cast<i128>(b.dx()) * a.dy();
}

}  // namespace scantrace
