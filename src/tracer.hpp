#pragma once
// What the fill tells a tracer, as plain value types (no JSON here: trace/ turns them into the
// events of design.md §5).
//
// The fill is a template over its tracer. A tracer declares the most detailed level it can ever
// want as `static constexpr TraceLevel max_level`; every hook call sits under `if constexpr` on it,
// so with NoTracer (max_level none) the fill compiles to exactly the untraced loop: no virtual
// call, no allocation, no "is tracing on" branch anywhere near the per-pixel loop. A tracer with a
// higher max_level also provides the runtime filters and the hooks of its levels:
//
//   bool wants_triangle(int triangle);            // level >= triangle
//   void triangle_begin(const PolygonSetup&);
//   void edge_table(const EdgeTableView&);
//   void triangle_end(int triangle, i64 rows, i64 pixels);
//   void triangle_skipped(int triangle, SkipReason);
//   bool wants_scanline(int triangle, i64 y);     // level >= scanline
//   void scanline(const ScanlineStep&);
//   bool wants_pixels(int triangle, i64 y);       // level == pixel
//   void pixel(int triangle, i64 x, i64 y, Color, double t);
#include <optional>
#include <span>

#include "color.hpp"
#include "edge_table.hpp"
#include "fill_options.hpp"
#include "fill_result.hpp"
#include "vec2.hpp"

namespace scantrace {

enum class TraceLevel { none = 0, triangle = 1, scanline = 2, pixel = 3 };

struct PolygonSetup {
  int triangle = 0;                // face index (position in the scene)
  std::span<const Vec2> vertices;  // as given
  std::span<const FixedPoint> snapped;
  std::span<const Color> colors;
  std::optional<double> depth;
  Color flat_color;
  const FillOptions* options = nullptr;
  SubpixelGrid grid;
  // General polygons (winding_fill.hpp): the vertex count of each contour, whose vertices follow
  // one another in `vertices`. Empty for a single contour (triangles, convex polygons).
  std::span<const int> contour_sizes = {};
  std::span<const double> vertex_depths = {};  // z-buffer renders: PolygonInput::vertex_depths
};

struct EdgeTableView {
  int triangle = 0;
  const EdgeTable* table = nullptr;
  std::span<const FixedPoint> snapped;
  SubpixelGrid grid;
};

struct ActiveEdgeState {
  int edge = 0;
  double x = 0;     // exact intersection with the row (rounded to double for display)
  i64 ceil_x = 0;   // ceil(x), computed exactly
  int winding = 0;  // general polygons: +1 edge going down, -1 up; 0 = not reported (convex fill)
};

struct ActivePointState {
  double x = 0;
  int edge = 0;
  Color color;  // interpolated along the edge (Gouraud) or the flat colour
};

// One inside interval of a row of a general polygon: between the active edge where the winding
// rule turns "inside" and the one where it turns "outside" again.
struct IntervalState {
  int left_edge = 0, right_edge = 0;
  double x_left = 0, x_right = 0;  // the two edges' exact intersections with the row
  i64 x_begin = 0, x_end = 0;      // its pixels, half-open, clipped to the canvas (may be empty)
  bool has_colors = false;
  Color begin, end;  // colours of pixels x_begin and x_end - 1 (Gouraud)
};

struct ScanlineStep {
  int triangle = 0;
  i64 y = 0;
  std::span<const int> entered, retired;
  std::span<const ActiveEdgeState> active_edges;
  std::span<const ActivePointState> active_points;
  bool has_span = false;
  i64 x_begin = 0, x_end = 0;  // half-open, clipped to the canvas
  bool has_span_colors = false;
  Color span_begin, span_end;  // colours of pixels x_begin and x_end - 1 (Gouraud)
  // General polygons: every inside interval with at least one pixel, left to right; the span
  // above is then the first of them. Convex fills leave has_intervals false.
  bool has_intervals = false;
  std::span<const IntervalState> intervals = {};
};

// The default: traces nothing, costs nothing.
struct NoTracer {
  static constexpr TraceLevel max_level = TraceLevel::none;
};

template <class T>
concept FillTracer = requires {
  { T::max_level } -> std::convertible_to<TraceLevel>;
};

}  // namespace scantrace
