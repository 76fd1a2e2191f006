#pragma once
// When the whole triangle fits the view only with cells too small for a grid (the 280x380 demo
// triangle gets ~1.5 px per pixel at 720p), the ends of the current span are what a student
// needs to see pixel by pixel: where the edge crosses the row, which pixel centre is the first and
// the last inside. A span that fits in one inset gets one, centred on it; a wider one gets an
// inset for each end, and the two never show the same canvas pixel. Each inset is drawn at 18
// design pixels a canvas pixel, at the place of a 9 x 9 grid over the view that covers no marker,
// no label and not the span, and hides least of what the frames have filled so far, then of the
// rest of the polygon and of the scanline; a smaller inset over empty canvas is preferred to a
// large one over filled pixels, and where nothing is free at all they are left out (the view
// never loses a vertex or an x value to them).
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
