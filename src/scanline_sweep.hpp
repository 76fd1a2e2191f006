#pragma once
// The scanline sweep: the algorithm every edge-table fill shares, read top to bottom.
//
//   edge table  →  active edge list  →  per row: the edges' crossings  →  spans  →  consumers
//
// The edge table (edge_table.hpp) lists a polygon's non-horizontal edges by their first row. The
// sweep walks the rows the polygon covers on the canvas; on each row the active edge list
// (active_edge_list.hpp) lets the edges that start enter and those that ended retire, and holds
// where each active edge crosses the row, exactly (edge_stepper.hpp). A `RowRule` turns the
// row's crossings into spans (span.hpp) and hands them to the row's consumers: the canvas, which
// writes the pixels, and the tracer (row_trace.hpp), which is told what happened. The sweep knows
// neither: like Anti-Grain Geometry's `while (ras.sweep_scanline(sl)) ren.render(sl);` it only
// produces rows.
//
// The rules (the only difference between the fills):
//   convex polygon  (scanline_fill.hpp)  one span, from the leftmost crossing to the rightmost;
//   general polygon (winding_fill.hpp)   windings summed left to right, one span per interval the
//                                        winding rule puts inside.
//
// Rows come in runs. The active list changes only on rows where an edge starts or ends, so the
// sweep updates it there and hands the rule the whole run of rows up to the next such event; a
// rule can then keep the steppers of the run in registers (the convex fill's speed comes from
// that). A rule provides:
//
//   void begin_row(i64 y);               // before anything happens on row y (the tracer decides)
//   void entered(const Edge&);           // an edge entered the list on the current row
//   void retired(const Edge&);           // an edge left it
//   void run(i64 y, i64 last, ActiveEdgeList<Stepper>&);
//                                        // rows y … last: crossings → spans → consumers; steps
//                                        // every active edge past each row
#include <algorithm>
#include <span>

#include "active_edge_list.hpp"
#include "canvas.hpp"
#include "color.hpp"
#include "edge_stepper.hpp"
#include "edge_table.hpp"
#include "fill_options.hpp"
#include "fixed_point.hpp"

namespace scantrace {

// Always inlined into its caller, together with the rule's run (scanline_fill.hpp): a small
// triangle is one or two runs of a few rows, and calls, spills and reloads between the sweep and
// the run would cost a noticeable share of its fill (docs/performance.md, "Why the fast code looks as it does").
template <class Stepper, class RowRule>
[[gnu::always_inline]] inline void sweep_scanlines(const EdgeTable& table, RowBand band,
                                                   const SubpixelGrid& grid,
                                                   std::span<const Color> colors,
                                                   ActiveEdgeList<Stepper>& active, RowRule& rule) {
  // Only the rows on the canvas (or its band) are visited: an edge that starts above it enters
  // on the first visible row, its stepper started there directly, never stepped through the rows
  // before.
  const i64 y_first = std::max<i64>(table.first_row(), band.begin);
  const i64 y_last = std::min<i64>(table.last_row(), band.end - 1);
  active.reset(table);
  for (i64 y = y_first; y <= y_last;) {
    rule.begin_row(y);
    active.retire(y, [&](const Edge& e) { rule.retired(e); });
    active.enter(y, grid, colors, [&](const Edge& e) { rule.entered(e); });
    const i64 last = active.run_last(y_last);
    rule.run(y, last, active);
    y = last + 1;
  }
}

// The ActiveEdgeList of the method's stepper, called as f.template operator()<Stepper>(): the one
// place where a fill's method becomes a type.
template <class F>
decltype(auto) with_stepper(Method method, F&& f) {
  switch (method) {
    case Method::float32:
      return f.template operator()<FloatStepper>();
    case Method::double64:
      return f.template operator()<DoubleStepper>();
    default:
      return f.template operator()<ExactStepper>();
  }
}

}  // namespace scantrace
