#pragma once
// When the whole triangle fits the view only with cells too small for a grid (the 280x380 demo
// triangle gets ~1.5 px per pixel at 720p), the ends of the current span are what a student
// needs to see pixel by pixel: where the edge crosses the row, which pixel centre is the first and
// the last inside. Each end gets a magnified inset in a corner of the view, the corner chosen to
// cover as little of the triangle as possible.
#include <opencv2/core.hpp>

#include "trace/trace.hpp"
#include "viz/canvas_state.hpp"
#include "viz/typography.hpp"
#include "viz/view_geometry.hpp"

namespace scantrace::viz {

void draw_zoom_insets(cv::Mat& frame, const ViewGeometry& main, const Typography& type,
                      cv::Size canvas, const CanvasState& state, const trace::TriangleBegin* b,
                      const trace::EdgeTableEvent* table, const trace::Scanline& row);

}  // namespace scantrace::viz
