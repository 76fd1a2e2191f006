#pragma once
// The left half of a frame: the canvas around the triangle, magnified, with the marks of
// docs/design.md §6 — pixel cells in their written colours, the pixel grid and centres (when cells are
// big enough to show them), the exact outline, the current scanline, the active edges, the active
// points with their x, the span, the vertices.
#include <cstdint>
#include <span>

#include <opencv2/core.hpp>

#include "trace/events.hpp"
#include "viz/canvas_state.hpp"
#include "viz/typography.hpp"
#include "viz/view_geometry.hpp"

namespace scantrace::viz {

class GridView {
 public:
  // Below this cell size (frame pixels) grid lines and centres would only darken the picture.
  static constexpr double kMinGridCell = 6;

  GridView(cv::Mat& frame, const ViewGeometry& geometry, const Typography& type, cv::Size canvas);

  bool grid_visible() const { return geometry_.cell() >= kMinGridCell; }

  // The written pixels in their colours; unwritten ones as empty cells, or in `background` (the
  // finished image as rendered).
  void cells(const CanvasState& state, std::optional<Color> background = std::nullopt);
  void grid();
  void outline(std::span<const Vec2> polygon, const cv::Scalar& colour, double design_thickness);
  // Every closed contour of the polygon (one for a triangle).
  void outline(const trace::TriangleBegin& polygon, const cv::Scalar& colour,
               double design_thickness);
  // An edge of the edge table in its own colour; `active` ones are drawn bold.
  void edge(Vec2 from, Vec2 to, int id, bool active);
  void vertices(const trace::TriangleBegin& triangle);
  void scanline(std::int64_t y, bool labelled = true);
  void span(std::int64_t y, const trace::Span& span);
  // The row's span, or every inside interval of a general polygon's row.
  void spans(const trace::Scanline& row);
  void active_points(const trace::Scanline& row);

 private:
  cv::Point2d at(double x, double y) const { return geometry_.to_frame(x, y); }
  // Keeps a label of size `s` whose top-left would be `p` inside the view.
  cv::Point inside(cv::Point p, cv::Size s) const;

  cv::Mat& frame_;
  const ViewGeometry& geometry_;
  const Typography& type_;
  cv::Size canvas_;
};

}  // namespace scantrace::viz
