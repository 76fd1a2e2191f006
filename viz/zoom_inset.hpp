#pragma once
// When the whole triangle fits the view only with cells too small for a grid (the 280x380 demo
// triangle gets ~1.5 px per pixel at 720p), the ends of the current span are what a student
// needs to see pixel by pixel: where the edge crosses the row, which pixel centre is the first and
// the last inside. Each end gets a magnified inset at a corner or the middle of a side of the view,
// chosen among the places that cover no marker and no label to hide as little of the polygon as
// possible; where nothing is free at full size the insets shrink, and where nothing is free at all
// they are left out (the view never loses a vertex or an x value to them).
#include <vector>

#include "viz/frame.hpp"

#include "trace/trace.hpp"
#include "viz/canvas_state.hpp"
#include "viz/label_placement.hpp"
#include "viz/typography.hpp"
#include "viz/view_geometry.hpp"

namespace scantrace::viz {

// `placed` holds the view's markers and labels; the insets are added to it, and what was placed
// inside them is returned (layers 1 and 2).
std::vector<PlacedBox> draw_zoom_insets(FrameView& frame, const ViewGeometry& main,
                                        const Typography& type, Size canvas,
                                        const CanvasState& state, const trace::TriangleBegin* b,
                                        const trace::EdgeTableEvent* table,
                                        const trace::Scanline& row, Placement& placed);

}  // namespace scantrace::viz
