#pragma once
// What filling one polygon did.
#include "fixed_point.hpp"

namespace scantrace {

enum class SkipReason {
  none,
  too_few_vertices,  // fewer than three vertices
  out_of_range,      // a coordinate is NaN, infinite or beyond kMaxCoordinate
  degenerate,        // zero area after snapping: fills nothing under either rule
  no_pixel_centre,   // its bounding box holds no pixel centre: too small to own a pixel
  offscreen,         // no row or no column of its bounding box is on the canvas
  culled,            // facing away (or towards) the viewer, as FillOptions::cull asks
  hidden,            // its box is all covered by nearer faces (the near-to-far render, painter.hpp)
};
const char* to_string(SkipReason r);

struct FillResult {
  SkipReason skipped = SkipReason::none;
  i64 rows = 0;    // scanlines visited (on the canvas)
  i64 pixels = 0;  // pixels written
};

}  // namespace scantrace
