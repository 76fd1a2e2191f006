#pragma once
// The left half of a frame: the canvas around the triangle, magnified, with the marks of
// docs/design.md §6 — pixel cells in their written colours, the pixel grid and centres (when cells
// are big enough to show them), the exact outline, the current scanline, the active edges, the
// active points with their x, the span, the vertices. Markers are drawn where the geometry puts
// them; their labels are placed where they cover no marker and no other label
// (viz/label_placement.hpp), so the order of the calls is the order of importance: all markers,
// then the labels that matter most for the step.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "viz/frame.hpp"

#include "trace/events.hpp"
#include "viz/canvas_state.hpp"
#include "viz/label_placement.hpp"
#include "viz/typography.hpp"
#include "viz/view_geometry.hpp"

namespace scantrace::viz {

class GridView {
 public:
  // Below this cell size (frame pixels) grid lines and centres would only darken the picture.
  static constexpr double kMinGridCell = 6;

  // `layer` numbers the view in the placements it reports: 0 the main view, k a zoom inset.
  GridView(FrameView& frame, const ViewGeometry& geometry, const Typography& type, Size canvas,
           int layer = 0);

  bool grid_visible() const { return geometry_.cell() >= kMinGridCell; }

  // The written pixels in their colours; unwritten ones as empty cells, or in `background` (the
  // finished image as rendered).
  void cells(const CanvasState& state, std::optional<Color> background = std::nullopt);
  void grid();
  void outline(std::span<const Vec2> polygon, const Scalar& colour, double design_thickness);
  // Every closed contour of the polygon (one for a triangle).
  void outline(const trace::TriangleBegin& polygon, const Scalar& colour, double design_thickness);
  // An edge of the edge table in its own colour; `active` ones are drawn bold.
  void edge(Vec2 from, Vec2 to, int id, bool active);
  // Markers, then labels "v0 (x, y)", each away from the polygon's centre where there is room.
  void vertices(const trace::TriangleBegin& triangle);
  void vertex_markers(const trace::TriangleBegin& triangle);
  void vertex_labels(const trace::TriangleBegin& triangle);
  // The row's line across the view, and its label "y = N" at the view's left edge or wherever
  // along the row there is room.
  void scanline(std::int64_t y);
  void scanline_label(std::int64_t y);
  void span(std::int64_t y, const trace::Span& span);
  // The row's span, or every inside interval of a general polygon's row.
  void spans(const trace::Scanline& row);
  // Markers, then the labels "x = 12.34": the leftmost left of its point, the rightmost right of
  // it, the ones between above or below, or wherever around the point there is room.
  void active_points(const trace::Scanline& row);
  void active_point_markers(const trace::Scanline& row);
  void active_point_labels(const trace::Scanline& row);

  // What is on the view so far, for more marks placed around them (zoom insets) and for tests.
  Placement& placement() { return placement_; }
  const Placement& placement() const { return placement_; }

 private:
  Point2d at(double x, double y) const { return geometry_.to_frame(x, y); }
  // Draws `text` boxed in the first free area of `candidates` (areas of boxed_area's size);
  // nothing when none is free.
  void label(const std::string& text, TextStyle style, const std::vector<Rect>& candidates,
             const Scalar& box, std::optional<Scalar> border = std::nullopt);
  // Label areas for `text` around a marker at `p`, towards `preferred` first.
  std::vector<Rect> around(const std::string& text, TextStyle style, bool bold_border, Point2d p,
                           int radius, Point2d preferred) const;

  Vec3b cell_colour(Point p) const;
  // A mark of this view (its layer), `box` in the view's frame coordinates.
  Mark mark(MarkKind kind, const Rect& box, std::string what) const;

  FrameView& frame_;
  const ViewGeometry& geometry_;
  const Typography& type_;
  Size canvas_;
  Placement placement_;
  std::shared_ptr<const std::vector<Vec3b>> cells_;  // what cells() drew over the view, by rows
};

}  // namespace scantrace::viz
