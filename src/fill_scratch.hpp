#pragma once
// Working storage of the edge-table fills, reusable across polygons: a renderer keeps one and
// allocates nothing per polygon once the vectors have grown to their working size.
#include <type_traits>
#include <vector>

#include "active_edge_list.hpp"
#include "edge_stepper.hpp"
#include "edge_table.hpp"
#include "fixed_point.hpp"
#include "fast/flat_span.hpp"
#include "row_trace.hpp"

namespace scantrace {

struct FillScratch {
  std::vector<FixedPoint> snapped;
  std::vector<int> order;  // flat_color's
  EdgeTable table;
  ActiveEdgeList<ExactStepper> active_exact;
  ActiveEdgeList<DoubleStepper> active_double;
  ActiveEdgeList<FloatStepper> active_float;
  RowTraceScratch trace;  // only used when tracing rows
  FlatRow flat_row;       // long flat spans on a DirectCanvas

  template <class Stepper>
  ActiveEdgeList<Stepper>& active() {
    if constexpr (std::is_same_v<Stepper, ExactStepper>)
      return active_exact;
    else if constexpr (std::is_same_v<Stepper, DoubleStepper>)
      return active_double;
    else
      return active_float;
  }
};

// A general polygon's (winding_fill.hpp): its contours' vertices one after another.
struct WindingScratch : FillScratch {
  std::vector<Vec2> points;  // global vertex ids
  std::vector<int> sizes;    // vertices per contour
};

}  // namespace scantrace
