#pragma once
// What every row rule of the sweep (scanline_sweep.hpp) holds: the row's consumers — the canvas
// that writes its spans and the tracer told about it (row_trace.hpp) — and what it needs to
// colour a span. A rule adds its `run` (crossings → spans); the sweep's edge events go to the
// tracer as they are.
#include <span>

#include "canvas.hpp"
#include "color.hpp"
#include "edge.hpp"
#include "fill_options.hpp"
#include "fill_result.hpp"
#include "fixed_point.hpp"
#include "row_trace.hpp"

namespace scantrace {

template <Canvas C, class Tracer>
struct RowRule {
  C& canvas;
  std::span<const Color> colors;  // one per vertex
  const SubpixelGrid& grid;
  const FillOptions& opt;
  Color flat;  // the flat colour (or, for equal Gouraud colours, that colour)
  RowTrace<Tracer>& trace;
  i64 rows = 0, pixels = 0;  // visited, written

  void begin_row(i64 y) { trace.begin_row(y); }
  void entered(const Edge& e) { trace.entered(e); }
  void retired(const Edge& e) { trace.retired(e); }
  FillResult result() const { return {SkipReason::none, rows, pixels}; }
};

}  // namespace scantrace
