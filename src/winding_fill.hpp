#pragma once
// The full edge-table fill of a general polygon: concave, self-intersecting, with holes (several
// contours), under the even-odd or the non-zero winding rule (docs/polygons.md).
//
// The convex fill (scanline_fill.hpp) knows that a row meets its polygon in one interval between
// exactly two active edges. Here any even number of edges can be active, and they can cross one
// another between rows, so on each row the sweep
//   1. retires and enters edges as the convex sweep does (same edge table, same exact stepper),
//   2. re-sorts the active list by exact x (edges that crossed since the last row swap places;
//      the list is nearly sorted, so an insertion sort is linear in practice),
//   3. walks it left to right summing each edge's winding (+1 going down, -1 going up), and fills
//      the pixels between the edge where the rule turns "inside" and the one where it turns
//      "outside" again — the row's inside intervals.
//
// Pixel ownership generalises the top-left rule of design.md §3. A pixel centre (x, y) is inside
// iff the winding rule holds for the edges crossing row y at x_c <= x, where an edge crosses row y
// iff y_top <= y < y_bottom. That is the winding at the centre moved down by an infinitesimal δ
// and right by an infinitesimal ε >> δ. So an interval between crossings x_L and x_R owns the
// pixels [ceil(x_L), ceil(x_R)): for a convex polygon exactly the span of the convex fill, and two
// polygons sharing an edge (or a polygon and one filling its hole) still tile — the shared edge's
// crossing is x_c <= x for both or for neither, and the δ-shifted point lies on one side of it.
//
// Colours (Gouraud): the vertex colours interpolated along each edge to the row, as the convex
// fill does, then linearly along each inside interval between its two bounding edges' colours.
// Under non-zero, edges inside a region of winding 2 do not bound an interval: the interval runs
// from the region's left boundary to its right one. Flat: the mean of all vertex colours.
//
// Only the top-left rule is defined here: the closed rule's "centres on the boundary too" has no
// single meaning where edges cross or contours touch, so fill_polygon_contours rejects it.
#include <algorithm>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "canvas.hpp"
#include "edge_stepper.hpp"
#include "edge_table.hpp"
#include "fill_options.hpp"
#include "fill_result.hpp"
#include "tracer.hpp"

namespace scantrace {

// Built with SCANTRACE_NO_TRACE_HOOKS, the fill contains no hook call at all (as the convex fill).
#ifdef SCANTRACE_NO_TRACE_HOOKS
inline constexpr bool kWindingTraceHooks = false;
#else
inline constexpr bool kWindingTraceHooks = true;
#endif

// Working storage, reusable across polygons (nothing is allocated once it has grown).
struct WindingScratch {
  std::vector<FixedPoint> snapped;
  std::vector<Vec2> points;  // the contours' vertices one after another (global vertex ids)
  std::vector<int> sizes;    // vertices per contour
  EdgeTable table;
  std::vector<ActiveEdge<ExactStepper>> active_exact;
  std::vector<ActiveEdge<DoubleStepper>> active_double;
  std::vector<ActiveEdge<FloatStepper>> active_float;
  // Only used when tracing.
  std::vector<int> entered, retired;
  std::vector<ActiveEdgeState> active_states;
  std::vector<ActivePointState> active_points;
  std::vector<IntervalState> intervals;

  template <class Stepper>
  std::vector<ActiveEdge<Stepper>>& active() {
    if constexpr (std::is_same_v<Stepper, ExactStepper>)
      return active_exact;
    else if constexpr (std::is_same_v<Stepper, DoubleStepper>)
      return active_double;
    else
      return active_float;
  }
};

namespace winding_detail {

// Exact row order, then slope (the order just below the row), then id: a total order, so the
// walk — and with it which edge bounds an interval — never depends on the sort's history.
template <class Stepper>
bool ordered(const ActiveEdge<Stepper>& a, const ActiveEdge<Stepper>& b) {
  if (before_on_row(a, b)) return true;
  if (before_on_row(b, a)) return false;
  return a.edge.id < b.edge.id;
}

inline bool inside(int winding, WindingRule rule) {
  return rule == WindingRule::even_odd ? (winding & 1) != 0 : winding != 0;
}

struct Setup {
  SubpixelGrid grid;
  Color flat;
  int polygon = 0;
  bool traced = false;
};

template <class Stepper, Canvas C, FillTracer Tracer>
FillResult sweep(C& canvas, std::span<const Color> colors, const FillOptions& opt,
                 WindingScratch& s, Tracer& tracer, const Setup& setup) {
  constexpr bool kScanlineLevel = kWindingTraceHooks && Tracer::max_level >= TraceLevel::scanline;
  constexpr bool kPixelLevel = kWindingTraceHooks && Tracer::max_level >= TraceLevel::pixel;
  const SubpixelGrid& grid = setup.grid;
  const bool gouraud = opt.shading == Shading::gouraud;
  const int width = canvas.width(), height = canvas.height();
  const std::vector<Edge>& edges = s.table.edges();
  const i64 y_first = std::max<i64>(s.table.first_row(), 0);
  const i64 y_last = std::min<i64>(s.table.last_row(), height - 1);
  std::vector<ActiveEdge<Stepper>>& active = s.active<Stepper>();
  active.clear();
  std::size_t next = 0;
  FillResult result;

  for (i64 y = y_first; y <= y_last; ++y) {
    [[maybe_unused]] bool trace_row = false;
    if constexpr (kScanlineLevel) {
      trace_row = setup.traced && tracer.wants_scanline(setup.polygon, y);
      s.entered.clear();
      s.retired.clear();
      s.intervals.clear();
    }
    std::erase_if(active, [&](const ActiveEdge<Stepper>& a) {
      if (a.edge.last_row >= y) return false;
      if constexpr (kScanlineLevel)
        if (trace_row) s.retired.push_back(a.edge.id);
      return true;
    });
    for (; next < edges.size() && edges[next].first_row <= y; ++next) {
      if (edges[next].last_row < y) continue;
      ActiveEdge<Stepper> a{edges[next], {}};
      a.at.start(a.edge, y, grid, colors);
      active.push_back(a);
      if constexpr (kScanlineLevel)
        if (trace_row) s.entered.push_back(a.edge.id);
    }
    // Insertion sort: only edges that crossed since the previous row (and the new ones) move.
    for (std::size_t i = 1; i < active.size(); ++i)
      for (std::size_t j = i; j > 0 && ordered(active[j], active[j - 1]); --j)
        std::swap(active[j], active[j - 1]);
    ++result.rows;

    int winding = 0;
    const ActiveEdge<Stepper>* open = nullptr;
    for (const ActiveEdge<Stepper>& a : active) {
      winding += a.edge.winding();
      const bool now = inside(winding, opt.winding_rule);
      if (now && !open) {
        open = &a;
        continue;
      }
      if (now || !open) continue;
      // An inside interval from `open` to `a`: pixels [ceil(x_L), ceil(x_R)), clipped.
      const ActiveEdge<Stepper>& l = *open;
      open = nullptr;
      const i64 x_begin = std::max<i64>(l.at.ceil_x(), 0);
      const i64 x_end = std::min<i64>(a.at.ceil_x(), width);
      if (x_begin >= x_end) continue;
      const int yi = static_cast<int>(y), xb = static_cast<int>(x_begin),
                xe = static_cast<int>(x_end);
      [[maybe_unused]] bool trace_pixels = false;
      if constexpr (kPixelLevel) trace_pixels = trace_row && tracer.wants_pixels(setup.polygon, y);
      const double xl = l.at.x(), xr = a.at.x();
      [[maybe_unused]] auto weight = [&](int x) { return xr > xl ? (x - xl) / (xr - xl) : 0.0; };
      [[maybe_unused]] Color first = setup.flat, last = setup.flat;
      if (!gouraud) {
        canvas.fill_span(yi, xb, xe, setup.flat);
        if constexpr (kPixelLevel)
          if (trace_pixels)
            for (int x = xb; x < xe; ++x) tracer.pixel(setup.polygon, x, y, setup.flat, weight(x));
      } else {
        // Each pixel evaluated from the interval's end colours: nothing accumulates along a long
        // interval, and it costs one multiply-add per channel.
        const Color cl = l.at.color(l.edge, y, colors, grid);
        const Color cr = a.at.color(a.edge, y, colors, grid);
        const Color slope = xr > xl ? (cr - cl) * (1.0 / (xr - xl)) : Color{};
        for (int x = xb; x < xe; ++x) {
          const Color c = cl + slope * (x - xl);
          canvas.set(x, yi, c);
          if constexpr (kPixelLevel)
            if (trace_pixels) tracer.pixel(setup.polygon, x, y, c, weight(x));
          if constexpr (kScanlineLevel)
            if (trace_row) {
              if (x == xb) first = c;
              last = c;
            }
        }
      }
      result.pixels += x_end - x_begin;
      if constexpr (kScanlineLevel)
        if (trace_row)
          s.intervals.push_back(
              {l.edge.id, a.edge.id, xl, xr, x_begin, x_end, gouraud, first, last});
    }

    if constexpr (kScanlineLevel) {
      if (trace_row) {
        s.active_states.clear();
        s.active_points.clear();
        for (const ActiveEdge<Stepper>& a : active) {
          s.active_states.push_back({a.edge.id, a.at.x(), a.at.ceil_x(), a.edge.winding()});
          s.active_points.push_back(
              {a.at.x(), a.edge.id, gouraud ? a.at.color(a.edge, y, colors, grid) : setup.flat});
        }
        ScanlineStep step;
        step.triangle = setup.polygon;
        step.y = y;
        step.entered = s.entered;
        step.retired = s.retired;
        step.active_edges = s.active_states;
        step.active_points = s.active_points;
        step.has_intervals = true;
        step.intervals = s.intervals;
        // `span` stays meaningful for readers that know one span per row: the first interval.
        if (!s.intervals.empty()) {
          const IntervalState& f = s.intervals.front();
          step.has_span = true;
          step.x_begin = f.x_begin;
          step.x_end = f.x_end;
          step.has_span_colors = f.has_colors;
          step.span_begin = f.begin;
          step.span_end = f.end;
        }
        tracer.scanline(step);
      }
    }
    for (ActiveEdge<Stepper>& a : active) a.at.advance();
  }
  return result;
}

}  // namespace winding_detail

// Fills the polygon whose closed contours are `contours` (each a list of vertices in pixels;
// holes are just more contours — under non-zero they must run the other way round to be holes),
// with one colour per vertex in `colors`, the contours' vertices one after another. Edge i of the
// trace runs from vertex i (in that global numbering) to the next vertex of its contour.
// `polygon` is the index the trace reports. Methods exact (default), double and float; the
// halfspace method and the closed fill rule are convex-only and rejected.
template <Canvas C, FillTracer Tracer = NoTracer>
FillResult fill_polygon_contours(C& canvas, std::span<const std::vector<Vec2>> contours,
                                 std::span<const Color> colors, const FillOptions& opt,
                                 WindingScratch& s, Tracer& tracer, int polygon = 0) {
  constexpr bool kTriangleLevel = kWindingTraceHooks && Tracer::max_level >= TraceLevel::triangle;
  [[maybe_unused]] bool traced = false;
  if constexpr (kTriangleLevel) traced = tracer.wants_triangle(polygon);
  auto skip = [&](SkipReason reason) {
    if constexpr (kTriangleLevel)
      if (traced) tracer.triangle_skipped(polygon, reason);
    return FillResult{reason, 0, 0};
  };

  const SubpixelGrid grid(opt.subpixel_bits);
  if (!grid.valid())
    throw std::invalid_argument("fill: subpixel_bits must be in 0…" +
                                std::to_string(kMaxSubpixelBits));
  if (opt.fill_rule == FillRule::closed)
    throw std::invalid_argument(
        "general polygons: the closed fill rule is not defined where edges cross or contours "
        "touch; use top-left (docs/polygons.md)");
  if (opt.method == Method::halfspace)
    throw std::invalid_argument(
        "general polygons: the halfspace method tests convex half-planes; use exact, double or "
        "float");
  s.points.clear();
  s.sizes.clear();
  for (const std::vector<Vec2>& c : contours) {
    s.points.insert(s.points.end(), c.begin(), c.end());
    s.sizes.push_back(static_cast<int>(c.size()));
  }
  const std::size_t n = s.points.size();
  if (colors.size() != n) throw std::invalid_argument("fill: one colour per vertex is needed");
  if (n < 3) return skip(SkipReason::too_few_vertices);
  s.snapped.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!SubpixelGrid::representable(s.points[i])) return skip(SkipReason::out_of_range);
    s.snapped[i] = grid.snap(s.points[i]);
  }
  {
    i64 x_min = s.snapped[0].x, x_max = x_min, y_min = s.snapped[0].y, y_max = y_min;
    for (const FixedPoint& p : s.snapped) {
      x_min = std::min(x_min, p.x), x_max = std::max(x_max, p.x);
      y_min = std::min(y_min, p.y), y_max = std::max(y_max, p.y);
    }
    const i64 col_first = grid.ceil_to_pixel(x_min), col_last = grid.ceil_to_pixel(x_max) - 1;
    const i64 row_first = grid.ceil_to_pixel(y_min), row_last = grid.ceil_to_pixel(y_max) - 1;
    if (col_first > col_last || row_first > row_last) return skip(SkipReason::no_pixel_centre);
    if (col_last < 0 || col_first >= canvas.width() || row_last < 0 || row_first >= canvas.height())
      return skip(SkipReason::offscreen);
  }
  Color flat;
  if (opt.shading == Shading::flat || traced) {
    for (const Color& c : colors) flat += c;
    flat = flat * (1.0 / static_cast<double>(n));
  }
  if constexpr (kTriangleLevel)
    if (traced) {
      PolygonSetup setup{polygon, s.points, s.snapped, colors, std::nullopt, flat, &opt, grid};
      setup.contour_sizes = s.sizes;
      tracer.triangle_begin(setup);
    }
  s.table.build_contours(s.snapped, s.sizes, grid, FillRule::top_left);
  if constexpr (kTriangleLevel)
    if (traced) tracer.edge_table(EdgeTableView{polygon, &s.table, s.snapped, grid});
  const winding_detail::Setup setup{grid, flat, polygon, traced};
  FillResult result;
  switch (opt.method) {
    case Method::float32:
      result = winding_detail::sweep<FloatStepper>(canvas, colors, opt, s, tracer, setup);
      break;
    case Method::double64:
      result = winding_detail::sweep<DoubleStepper>(canvas, colors, opt, s, tracer, setup);
      break;
    default:
      result = winding_detail::sweep<ExactStepper>(canvas, colors, opt, s, tracer, setup);
  }
  if constexpr (kTriangleLevel)
    if (traced) tracer.triangle_end(polygon, result.rows, result.pixels);
  return result;
}

template <Canvas C>
FillResult fill_polygon_contours(C& canvas, std::span<const std::vector<Vec2>> contours,
                                 std::span<const Color> colors, const FillOptions& opt,
                                 WindingScratch& s) {
  NoTracer none;
  return fill_polygon_contours(canvas, contours, colors, opt, s, none);
}

// Convenience entry point on an image.
template <class P, class Tracer = NoTracer>
requires FillTracer<std::remove_cvref_t<Tracer>> FillResult fill_polygon_contours(
    Image<P>& image, std::span<const std::vector<Vec2>> contours, std::span<const Color> colors,
    const FillOptions& opt = {}, Tracer&& tracer = NoTracer{}) {
  ImageCanvas<P> canvas(image);
  WindingScratch scratch;
  return fill_polygon_contours(canvas, contours, colors, opt, scratch, tracer);
}

}  // namespace scantrace
