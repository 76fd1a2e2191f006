#pragma once
// One face of a scene as the grader sees it: its vertices snapped to the fill's subpixel grid,
// and the exact questions asked about a pixel centre — covered under a fill rule, lying exactly on
// an edge or a vertex, within one pixel of the outline — plus the colour the face has there
// (flat mean or the barycentric Gouraud colour, extrapolated outside the face). Coverage is the
// exact reference's (src/exact_reference.hpp), not the fill's, so a grade never trusts the code it
// grades.
#include <array>
#include <optional>
#include <string>

#include "reference/exact_reference.hpp"
#include "src/color.hpp"
#include "src/fill_options.hpp"
#include "src/scene.hpp"

namespace scantrace::grade {

enum class OnOutline { no, edge, vertex };

class FaceGeometry {
 public:
  FaceGeometry(const Scene& scene, int face, int subpixel_bits);

  int face() const { return face_; }
  bool degenerate() const { return polygon_.degenerate(); }
  bool covers(int x, int y, FillRule rule) const { return polygon_.covers(x, y, rule); }
  // Whether the centre (x, y) is exactly on an edge (which one: `edge`, 0–2, from vertex i to i+1)
  // or a vertex; decided on the snapped vertices in integers.
  OnOutline on_outline(int x, int y, int* edge = nullptr) const;
  // Euclidean distance from the centre (x, y) to the face's outline (0 on it), in pixels.
  double distance_to_outline(double x, double y) const;
  // distance_to_outline(x, y) <= d, decided on squared lengths where they settle it (most
  // centres: diff asks it of every differing pixel), so the same answer without hypot's cost.
  bool outline_within(double x, double y, double d) const;
  // Whether the centre is inside the closed face or within `d` pixels of it.
  bool within(double x, double y, double d) const;
  // The face's colour at the centre (x, y): flat = mean of the vertex colours; Gouraud = the
  // barycentric interpolation, extrapolated (not clamped) outside the face. `colors` overrides
  // the vertex colours (a hypothesis of the colour diagnosis).
  Color color_at(double x, double y, Shading shading) const;
  Color color_at(double x, double y, Shading shading, const std::array<Color, 3>& colors) const;
  const std::array<Color, 3>& colors() const { return colors_; }
  const std::array<Vec2, 3>& snapped() const { return p_; }
  // Shape words for a missing face: "horizontal edge", "vertical edge", "sliver", "a few pixels".
  std::string shape(int pixels) const;

 private:
  std::array<double, 3> weights(double x, double y) const;
  bool beyond_box(double x, double y, double d) const;

  int face_ = 0;
  reference::Polygon polygon_;
  std::array<reference::GridPt, 3> g_{};
  std::array<Vec2, 3> p_{};
  std::array<Color, 3> colors_{};
  double twice_area_ = 0;
  reference::i64 scale_ = 1;
  std::array<double, 4> box_{};  // of the snapped vertices: x0, x1, y0, y1 (beyond_box)
  double box_abs_ = 0;           // |x0| + |x1| + |y0| + |y1|, for beyond_box's rounding slack
};

}  // namespace scantrace::grade
