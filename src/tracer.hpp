#pragma once
// What the fill tells a tracer, as plain value types (no JSON here: trace/ turns them into the
// events of docs/design.md §5).
//
// The fill is a template over its tracer. A tracer declares the most detailed level it can ever
// want as `static constexpr TraceLevel max_level`; every hook call sits under `if constexpr` on it,
// so with NoTracer (max_level none) the fill compiles to exactly the untraced loop: no virtual
// call, no allocation, no "is tracing on" branch anywhere near the per-pixel loop. A tracer with a
// higher max_level also provides the runtime filters and the hooks of its levels (the concept
// FillTracer below checks them):
//
//   bool wants_triangle(int face);                // level >= triangle
//   void triangle_begin(const PolygonSetup&);
//   void edge_table(const EdgeTableView&);
//   void triangle_end(int face, i64 rows, i64 pixels);
//   void triangle_skipped(int face, SkipReason);
//   bool wants_scanline(int face, i64 y);         // level >= scanline
//   void scanline(const ScanlineStep&);
//   bool wants_pixels(int face, i64 y);           // level == pixel
//   void pixel(int face, i64 x, i64 y, Color, double t);
//
// `face` is the polygon's index (its position in the scene) whatever its vertex count; the hooks
// keep the names of the trace events they become (format v1's "triangle_begin", …).
#include <concepts>
#include <optional>
#include <span>

#include "color.hpp"
#include "edge_table.hpp"
#include "fill_options.hpp"
#include "fill_result.hpp"
#include "span.hpp"
#include "vec2.hpp"

namespace scantrace {

// Built with SCANTRACE_NO_TRACE_HOOKS, the fills contain no hook call at all, whatever the tracer.
// Only the tracer-overhead benchmark uses it, to show side by side that the default no-op tracer
// costs exactly nothing (bench/tracer_overhead.cpp).
#ifdef SCANTRACE_NO_TRACE_HOOKS
inline constexpr bool kTraceHooks = false;
#else
inline constexpr bool kTraceHooks = true;
#endif

enum class TraceLevel { none = 0, triangle = 1, scanline = 2, pixel = 3 };

struct PolygonSetup {
  int face = 0;  // the face's index: its position in the scene (trace v1 key "triangle")
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
  int face = 0;
  const EdgeTable* table = nullptr;
  std::span<const FixedPoint> snapped;
  SubpixelGrid grid;
};

// Where an active edge crosses the row (the active edge list's entry as the tracer sees it; the
// list's own entry, with its stepper, is ActiveEdge<Stepper> in active_edge_list.hpp).
struct EdgeCrossing {
  int edge = 0;
  double x = 0;     // exact intersection with the row (rounded to double for display)
  i64 ceil_x = 0;   // ceil(x), computed exactly
  int winding = 0;  // general polygons: +1 edge going down, -1 up; 0 = not reported (convex fill)
};

// An active point: an active edge's crossing with the colour interpolated there, as the course
// draws it.
struct ActivePoint {
  double x = 0;
  int edge = 0;
  Color color;  // interpolated along the edge (Gouraud) or the flat colour
};

// One row of the sweep as a tracer sees it: the active edge list and the row's spans.
struct ScanlineStep {
  int face = 0;
  i64 y = 0;
  std::span<const int> entered, retired;  // edge ids that entered / retired on this row
  std::span<const EdgeCrossing> active_edges;
  std::span<const ActivePoint> active_points;
  // The row's span (a convex polygon has at most one; for a general polygon the first of
  // `intervals`, for readers that know one span per row). span.has_colors under Gouraud.
  bool has_span = false;
  Span span;
  // General polygons: every span with at least one pixel, left to right. Convex fills leave
  // has_intervals false.
  bool has_intervals = false;
  std::span<const Span> intervals = {};
};

// The default: traces nothing, costs nothing.
struct NoTracer {
  static constexpr TraceLevel max_level = TraceLevel::none;
};

// The hooks of each level, as the fills call them. A tracer must provide every hook of the levels
// up to its max_level: a misspelt or missing hook is then an error at the fill's call site naming
// the concept, not one deep inside the sweep.
template <class T>
concept TriangleHooks = requires(T& t, int i, i64 n, const PolygonSetup& s, const EdgeTableView& v,
                                 SkipReason r) {
  { t.wants_triangle(i) } -> std::convertible_to<bool>;
  t.triangle_begin(s);
  t.edge_table(v);
  t.triangle_end(i, n, n);
  t.triangle_skipped(i, r);
};

template <class T>
concept ScanlineHooks = requires(T& t, int i, i64 y, const ScanlineStep& step) {
  { t.wants_scanline(i, y) } -> std::convertible_to<bool>;
  t.scanline(step);
};

// pixel() may also take the pixel's DepthTest as a sixth argument (z-buffer renders).
template <class T>
concept PixelHooks = requires(T& t, int i, i64 x, i64 y, Color c, double w) {
  { t.wants_pixels(i, y) } -> std::convertible_to<bool>;
  t.pixel(i, x, y, c, w);
};

template <class T>
concept FillTracer = requires {
  { T::max_level } -> std::convertible_to<TraceLevel>;
}
&&(T::max_level < TraceLevel::triangle ||
   TriangleHooks<T>)&&(T::max_level < TraceLevel::scanline ||
                       ScanlineHooks<T>)&&(T::max_level < TraceLevel::pixel || PixelHooks<T>);

}  // namespace scantrace
