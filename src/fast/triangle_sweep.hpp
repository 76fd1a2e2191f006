#pragma once
// The scanline sweep of one triangle under the top-left rule, without an edge table.
//
// A triangle's edge table is always the same story: sorted by y its vertices are top, middle and
// bottom; the long edge runs from top to bottom down one side, and the other side is the edge
// top → middle for the rows above the middle vertex and middle → bottom for the rows from it on.
// Which side the long edge is on is the sign of one exact cross product. So the sweep of
// src/scanline_sweep.hpp, which builds the table, lets edges enter and retire and orders them by
// their exact crossings on each row where the list changes, reaches the same two runs with the
// same two edges on the same sides; here they are set up directly, which is most of the per-face
// work of a small triangle (docs/performance.md, "A sweep for triangles").
//
// The rows and spans are the convex rule's (src/scanline_fill.hpp, ConvexRows::run), fed the same
// edges started at the same rows, so every pixel and colour is the general sweep's, bit for bit.
// Only the exact method under the top-left rule takes this path: there each row has exactly two
// active edges, whose order a cross product decides (the closed rule can add a third edge on a
// vertex's row; the float and double steppers order edges by their rounded crossings). A traced
// triangle always takes the general sweep, whose edge events the trace shows.
#include <span>
#include <utility>

#include "src/active_edge_list.hpp"
#include "src/canvas.hpp"
#include "src/color.hpp"
#include "src/edge.hpp"
#include "src/edge_stepper.hpp"
#include "src/fixed_point.hpp"

namespace scantrace {

namespace detail {

// The edge between vertices i and j of a triangle under the top-left rule, its id the vertex it
// leaves going round the triangle (the edge table's numbering).
inline Edge triangle_edge(std::span<const FixedPoint> p, int i, int j, const SubpixelGrid& grid) {
  return edge_between(p.data(), i, j, j == (i + 1) % 3 ? i : j, grid, FillRule::top_left);
}

}  // namespace detail

// Sweeps the rows of triangle `p` (three snapped vertices, non-zero area) that lie in `band`,
// handing `rule` the same runs as sweep_scanlines would under the top-left rule.
template <class RowRule>
[[gnu::always_inline]] inline void sweep_triangle(std::span<const FixedPoint> p, RowBand band,
                                                  const SubpixelGrid& grid,
                                                  std::span<const Color> colors,
                                                  ActiveEdgeList<ExactStepper>& active,
                                                  RowRule& rule) {
  int top = 0, mid = 1, bottom = 2;
  if (p[mid].y < p[top].y) std::swap(top, mid);
  if (p[bottom].y < p[mid].y) std::swap(mid, bottom);
  if (p[mid].y < p[top].y) std::swap(top, mid);
  const Edge along = detail::triangle_edge(p, top, bottom, grid);
  const i64 y_first = std::max<i64>(along.first_row, band.begin);
  const i64 y_last = std::min<i64>(along.last_row, band.end - 1);
  if (y_first > y_last) return;
  // The middle vertex is right of the long edge when the cross product of top→bottom and
  // top→middle is negative (y points down); the long edge is then the left one. The area is not
  // zero, so neither side is ambiguous.
  const FixedPoint a = p[top], b = p[mid], c = p[bottom];
  const bool long_left =
      static_cast<i128>(c.x - a.x) * (b.y - a.y) < static_cast<i128>(c.y - a.y) * (b.x - a.x);
  ExactStepper along_at;
  along_at.start(along, y_first, grid, colors);
  const i64 middle_row = grid.ceil_to_pixel(b.y);  // the first row of the lower edge
  auto run = [&](const Edge& side, i64 from, i64 to) {
    ExactStepper side_at;
    side_at.start(side, from, grid, colors);
    if (long_left)
      active.hold(along, along_at, side, side_at);
    else
      active.hold(side, side_at, along, along_at);
    rule.begin_row(from);
    // The run steps along_at past row `to` in place (ConvexRows::run says why not in the list).
    if (long_left)
      rule.run(from, to, active, along_at, side_at);
    else
      rule.run(from, to, active, side_at, along_at);
  };
  if (y_first < middle_row)
    run(detail::triangle_edge(p, top, mid, grid), y_first, std::min(middle_row - 1, y_last));
  if (middle_row <= y_last)
    run(detail::triangle_edge(p, mid, bottom, grid), std::max(middle_row, y_first), y_last);
}

}  // namespace scantrace
