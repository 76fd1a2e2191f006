#pragma once
// The edge-table / active-edge-list scanline fill of a convex polygon (a triangle being the
// common case), flat or Gouraud, under the fill rules of design.md §3.
//
//   1. snap the vertices to the subpixel grid; reject what cannot fill a pixel (degenerate,
//      off the canvas) before any per-row work;
//   2. build the edge table: non-horizontal edges sorted by their first scanline;
//   3. sweep the scanlines that are on the canvas: retire edges that ended, let edges that start
//      enter the active list (kept in exact x order), take the span between the leftmost and
//      rightmost active points, clip it to the canvas and write it; step every active edge to
//      the next row exactly.
//
// Rows before the canvas are never iterated: an edge entering below its first row is started
// directly at the first visible row (Edge::start_at). Columns outside are clipped before writing.
#include <algorithm>
#include <array>
#include <cstring>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "canvas.hpp"
#include "depth_test.hpp"
#include "edge_stepper.hpp"
#include "edge_table.hpp"
#include "fill_options.hpp"
#include "halfspace_fill.hpp"
#include "tracer.hpp"
#include "vector_interp.hpp"

namespace scantrace {

// Built with SCANTRACE_NO_TRACE_HOOKS, the fill contains no hook call at all, whatever the tracer.
// Only the tracer-overhead benchmark uses it, to show side by side that the default no-op tracer
// costs exactly nothing (bench/tracer_overhead.cpp).
#ifdef SCANTRACE_NO_TRACE_HOOKS
inline constexpr bool kTraceHooks = false;
#else
inline constexpr bool kTraceHooks = true;
#endif

// One polygon to fill: its vertices (pixels) and one colour per vertex. `triangle` is the index
// the trace reports (the face index in a scene); `depth` is reported when known.
struct PolygonInput {
  std::span<const Vec2> points;
  std::span<const Color> colors;
  int triangle = 0;
  std::optional<double> depth;
  // Z-buffer renders: the depth of each vertex, which the trace records so that a replay can
  // redo every pixel's depth test (src/depth_plane.hpp). Empty otherwise.
  std::span<const double> vertex_depths = {};
};

// Working storage of the fill, reusable across polygons: a renderer keeps one and allocates
// nothing per triangle once the vectors have grown to their working size.
struct FillScratch {
  std::vector<FixedPoint> snapped;
  std::vector<int> order;
  EdgeTable table;
  std::vector<ActiveEdge<ExactStepper>> active_exact;
  std::vector<ActiveEdge<DoubleStepper>> active_double;
  std::vector<ActiveEdge<FloatStepper>> active_float;
  // Only used when tracing.
  std::vector<int> entered, retired;
  std::vector<ActiveEdgeState> active_states;
  std::vector<ActivePointState> active_points;
  // A row of the current polygon's flat colour in the canvas's pixel format (fill_flat_span).
  std::vector<unsigned char> pattern;

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

namespace detail {

// Twice the signed area, exactly.
inline i128 twice_area(std::span<const FixedPoint> p) {
  i128 a = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const FixedPoint u = p[i], v = p[i + 1 == n ? 0 : i + 1];
    a += static_cast<i128>(u.x) * v.y - static_cast<i128>(v.x) * u.y;
  }
  return a;
}

// The mean of the vertex colours, summed in a canonical order so that listing the same polygon's
// vertices in another order cannot change the last bit of the result.
inline Color mean_color(std::span<const FixedPoint> p, std::span<const Color> colors,
                        std::vector<int>& order) {
  if (p.size() == 3) {
    // A triangle: each channel's three values are summed smallest first, which is as canonical as
    // a vertex order and takes six min/max instructions instead of a sort whose branches the
    // processor cannot predict.
    const auto sum3 = [](double a, double b, double c) {
      const double lo = std::min(a, b), hi = std::max(a, b);
      return (std::min(lo, c) + std::max(lo, std::min(hi, c))) + std::max(hi, c);
    };
    return Color{sum3(colors[0].r, colors[1].r, colors[2].r),
                 sum3(colors[0].g, colors[1].g, colors[2].g),
                 sum3(colors[0].b, colors[1].b, colors[2].b)} *
           (1.0 / 3.0);
  }
  // Insertion sort: polygons are small, and std::sort's set-up costs more than three vertices.
  const auto before = [&](int a, int b) {
    return p[a].y != p[b].y ? p[a].y < p[b].y : p[a].x != p[b].x ? p[a].x < p[b].x : a < b;
  };
  order.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::size_t j = i;
    for (; j > 0 && before(static_cast<int>(i), order[j - 1]); --j) order[j] = order[j - 1];
    order[j] = static_cast<int>(i);
  }
  Color sum;
  for (int i : order) sum += colors[i];
  return sum * (1.0 / static_cast<double>(p.size()));
}

// Colours along one span, the way each method computes them.
template <class Stepper>
struct SpanShader {
  // exact: the course's linear interpolation along x, as one reciprocal per span (a division per
  // span, not per pixel) and one increment per pixel in double: the colour is linear along the
  // row, and 16,384 increments drift by ~1e-12, far inside the 1e-4 budget.
  Color c, step;
  SpanShader(Color left, Color right, double xl, double xr, i64 x_begin) {
    if (!(xr > xl)) {  // a span of one point: vector_interp's symmetric mean
      c = (left + right) * 0.5;
      return;
    }
    const double inv = 1.0 / (xr - xl);
    step = (right - left) * inv;
    c = left + step * (static_cast<double>(x_begin) - xl);
  }
  Color color() const { return c; }
  void next() { c += step; }
};

template <>
struct SpanShader<DoubleStepper> {
  // double: every pixel evaluated from the span's end colours, nothing accumulated.
  Color left, slope;
  double xl, x;
  SpanShader(Color l, Color r, double x_left, double x_right, i64 x_begin)
      : left(l),
        slope(x_right > x_left ? (r - l) * (1.0 / (x_right - x_left)) : Color{}),
        xl(x_left),
        x(static_cast<double>(x_begin)) {}
  Color color() const { return left + slope * (x - xl); }
  void next() { x += 1.0; }
};

template <>
struct SpanShader<FloatStepper> {
  // float: the textbook's c += Δc per pixel in float32.
  std::array<float, 3> c, dc;
  SpanShader(Color l, Color r, double x_left, double x_right, i64 x_begin) {
    const float w = static_cast<float>(x_right) - static_cast<float>(x_left);
    const float off = static_cast<float>(x_begin) - static_cast<float>(x_left);
    const std::array<double, 3> a{l.r, l.g, l.b}, b{r.r, r.g, r.b};
    for (int k = 0; k < 3; ++k) {
      dc[k] = w > 0 ? static_cast<float>(b[k] - a[k]) / w : 0.0f;
      c[k] = static_cast<float>(a[k]) + off * dc[k];
    }
  }
  Color color() const { return {c[0], c[1], c[2]}; }
  void next() {
    for (int k = 0; k < 3; ++k) c[k] += dc[k];
  }
};

// The colour along an active edge during a run of rows, for Gouraud spans. By default the stepper
// gives it row by row; the exact method evaluates the edge's linear colour function at the row,
// c_top + (y − y_top)·Δc/Δy with the slope computed once per run: no division per row, and no
// accumulation either, so a row's colour does not depend on where its run began (a band of the
// parallel render begins runs at its own first row and must draw the same bits).
template <class Stepper>
struct RunEdgeColor {
  void start(const Edge&, std::span<const Color>, const SubpixelGrid&) {}
  Color at(const Stepper& s, const Edge& e, i64 y, std::span<const Color> c,
           const SubpixelGrid& g) const {
    return s.color(e, y, c, g);
  }
};

template <>
struct RunEdgeColor<ExactStepper> {
  Color top, slope;
  double y_top = 0;
  void start(const Edge& e, std::span<const Color> colors, const SubpixelGrid& grid) {
    const double scale = static_cast<double>(grid.scale());
    top = colors[e.top];
    slope = (colors[e.bottom] - top) * (scale / static_cast<double>(e.dy()));
    y_top = static_cast<double>(e.p_top.y) / scale;
  }
  Color at(const ExactStepper&, const Edge&, i64 y, std::span<const Color>,
           const SubpixelGrid&) const {
    return top + slope * (static_cast<double>(y) - y_top);
  }
};

// A flat span of a direct canvas. Short spans (the common case) are a plain loop; long ones are
// one memcpy from a row of the polygon's colour kept in `pattern`, which is built on the first long
// span and grown geometrically, so a large flat polygon is written at memcpy speed.
template <class P>
void fill_flat_span(P* out, int n, P value, std::vector<unsigned char>& pattern,
                    std::size_t& pattern_pixels) {
  constexpr int kShort = 32;
  if (n <= kShort) {
    for (int k = 0; k < n; ++k) out[k] = value;
    return;
  }
  const auto need = static_cast<std::size_t>(n);
  if (pattern_pixels < need) {
    pattern_pixels = std::max(need, 2 * pattern_pixels);
    pattern.resize(pattern_pixels * sizeof(P));
    for (std::size_t k = 0; k < pattern_pixels; ++k)
      std::memcpy(pattern.data() + k * sizeof(P), &value, sizeof(P));
  }
  std::memcpy(out, pattern.data(), need * sizeof(P));
}

// One pixel to the pixel-level trace, with the outcome of its depth test when the canvas tests
// depth and the tracer takes it (the canvas has just written the pixel: a span's pixels are
// narrated right after fill_span).
template <class Tracer, class C>
void trace_pixel(Tracer& tracer, const C& canvas, int triangle, int x, i64 y, Color c, double t) {
  if constexpr (DepthTestingCanvas<C> &&
                requires { tracer.pixel(triangle, x, y, c, t, canvas.depth_test(x)); })
    tracer.pixel(triangle, x, y, c, t, canvas.depth_test(x));
  else
    tracer.pixel(triangle, x, y, c, t);
}

// What the set-up hands to the sweep.
struct Setup {
  SubpixelGrid grid;
  Color flat;
  bool traced = false;
  bool uniform = false;  // Gouraud with three equal colours: every pixel is `flat`
};

// Step 3 of the fill for one stepper: the scanline sweep over the canvas rows.
//
// The active list changes only on the rows where an edge starts or ends. The sweep is therefore a
// sequence of runs: at the first row of a run the list is updated (edges retire, edges enter in x
// order), and every row of the run is then the same few steps, two ceilings, one span and two
// increments. Within a run the outermost edges' steppers live in local variables: the canvas is
// written through byte pointers, which may alias anything, so steppers kept in the list would be
// reloaded and stored around every span.
template <class Stepper, Canvas C, FillTracer Tracer>
FillResult sweep(C& canvas, const PolygonInput& in, const FillOptions& opt, FillScratch& s,
                 Tracer& tracer, const Setup& setup) {
  constexpr bool kScanlineLevel = kTraceHooks && Tracer::max_level >= TraceLevel::scanline;
  constexpr bool kPixelLevel = kTraceHooks && Tracer::max_level >= TraceLevel::pixel;
  const SubpixelGrid& grid = setup.grid;
  const bool closed = opt.fill_rule == FillRule::closed;
  const bool gouraud = opt.shading == Shading::gouraud;
  // Interpolating equal colours gives the same colour everywhere: such a polygon is filled as a
  // flat one (the trace still reports Gouraud span colours, which are that colour).
  const bool shade = gouraud && !setup.uniform;
  const int width = canvas.width();
  const std::vector<Edge>& edges = s.table.edges();
  const RowBand band = canvas_rows(canvas);
  const i64 y_first = std::max<i64>(s.table.first_row(), band.begin);
  const i64 y_last = std::min<i64>(s.table.last_row(), band.end - 1);
  std::vector<ActiveEdge<Stepper>>& active = s.active<Stepper>();
  active.clear();
  std::size_t next = 0;
  i64 rows = 0, pixels = 0;
  [[maybe_unused]] std::size_t pattern_pixels = 0;  // of s.pattern, valid for this polygon
  [[maybe_unused]] const auto flat_pixel = [&] {
    if constexpr (DirectCanvas<C>)
      return C::convert(setup.flat);
    else
      return 0;
  }();

  for (i64 y = y_first; y <= y_last;) {
    [[maybe_unused]] bool trace_row = false;
    if constexpr (kScanlineLevel) {
      trace_row = setup.traced && tracer.wants_scanline(in.triangle, y);
      if (trace_row) s.entered.clear(), s.retired.clear();
    }
    // Retire the edges whose last row is behind us (keeping the others in order).
    std::size_t kept = 0;
    for (std::size_t i = 0; i < active.size(); ++i) {
      if (active[i].edge.last_row >= y) {
        if (kept != i) active[kept] = active[i];
        ++kept;
      } else if constexpr (kScanlineLevel) {
        if (trace_row) s.retired.push_back(active[i].edge.id);
      }
    }
    active.resize(kept);
    // Let the edges that start by this row enter, in x order (an insertion step: the list holds
    // two or three edges). An edge whose rows all lie above the canvas, or that crosses no
    // scanline, is passed over without being stepped.
    for (; next < edges.size() && edges[next].first_row <= y; ++next) {
      if (edges[next].last_row < y) continue;
      active.push_back({edges[next], {}});
      active.back().at.start(edges[next], y, grid, in.colors);
      for (std::size_t k = active.size() - 1; k > 0 && before_on_row(active[k], active[k - 1]); --k)
        std::swap(active[k], active[k - 1]);
      if constexpr (kScanlineLevel)
        if (trace_row) s.entered.push_back(edges[next].id);
    }
    i64 run_last = next < edges.size() ? edges[next].first_row - 1 : y_last;
    for (const ActiveEdge<Stepper>& a : active) run_last = std::min(run_last, a.edge.last_row);
    run_last = std::min(run_last, y_last);

    // The run y … run_last.
    const std::size_t n_active = active.size();
    const Edge* left = n_active >= 2 ? &active.front().edge : nullptr;
    const Edge* right = n_active >= 2 ? &active.back().edge : nullptr;
    Stepper l = n_active >= 2 ? active.front().at : Stepper{};
    Stepper r = n_active >= 2 ? active.back().at : Stepper{};
    RunEdgeColor<Stepper> l_color, r_color;
    if (shade && left) {
      l_color.start(*left, in.colors, grid);
      r_color.start(*right, in.colors, grid);
    }
    rows += run_last - y + 1;
    for (;; ++y) {
      if constexpr (kScanlineLevel) {
        if (trace_row && n_active >= 2) active.front().at = l, active.back().at = r;
      }
      // A convex polygon meets a scanline in one interval: from the leftmost to the rightmost
      // active point. (Under the top-left rule exactly two edges are active; the closed rule can
      // add the two edges meeting at a vertex that lies exactly on the row.)
      i64 x_begin = 0, x_end = 0;
      if (left) {
        x_begin = std::max<i64>(l.ceil_x(), 0);
        // Half-open span [ceil(xl), ceil(xr)): a centre exactly on the right edge belongs to the
        // neighbour on the right. The closed rule includes it: [ceil(xl), floor(xr)].
        x_end = std::min<i64>(closed ? r.floor_x() + 1 : r.ceil_x(), width);
      }
      const bool has_span = x_begin < x_end;
      Color c_left = setup.flat, c_right = setup.flat;
      double x_left = 0, x_right = 0;
      if (left && (shade || trace_row)) {
        x_left = l.x();
        x_right = r.x();
        if (shade) {
          c_left = l_color.at(l, *left, y, in.colors, grid);
          c_right = r_color.at(r, *right, y, in.colors, grid);
        }
      }

      [[maybe_unused]] Color span_first = setup.flat, span_last = setup.flat;
      if (has_span) {
        const int yi = static_cast<int>(y), xb = static_cast<int>(x_begin),
                  xe = static_cast<int>(x_end);
        [[maybe_unused]] bool trace_pixels = false;
        if constexpr (kPixelLevel) trace_pixels = trace_row && tracer.wants_pixels(in.triangle, y);
        [[maybe_unused]] auto weight = [&](int x) {
          return x_right > x_left ? (x - x_left) / (x_right - x_left) : 0.0;
        };
        if (!shade) {
          if constexpr (DirectCanvas<C>)
            fill_flat_span(canvas.row(yi) + xb, xe - xb, flat_pixel, s.pattern, pattern_pixels);
          else
            canvas.fill_span(yi, xb, xe, setup.flat);
          if constexpr (kPixelLevel)
            if (trace_pixels)
              for (int x = xb; x < xe; ++x)
                trace_pixel(tracer, canvas, in.triangle, x, y, setup.flat, weight(x));
        } else {
          SpanShader<Stepper> shade(c_left, c_right, x_left, x_right, x_begin);
          // The exact method's span is linear from its first pixel's colour, so an image canvas
          // writes it in its pixel format's fastest way (whether the row is traced or not, so that
          // tracing never changes a pixel); the loop below then only narrates.
          constexpr bool kCanvasShades = DirectCanvas<C> && std::is_same_v<Stepper, ExactStepper>;
          if constexpr (kCanvasShades) canvas.shade_span(yi, xb, xe, shade.c, shade.step);
          if constexpr (kScanlineLevel)
            if (trace_row) span_first = shade.color();
          if (!kCanvasShades || trace_row) {
            for (int x = xb; x < xe; ++x) {
              const Color c = shade.color();
              if constexpr (!kCanvasShades) canvas.set(x, yi, c);
              if constexpr (kPixelLevel)
                if (trace_pixels) trace_pixel(tracer, canvas, in.triangle, x, y, c, weight(x));
              if constexpr (kScanlineLevel)
                if (trace_row) span_last = c;
              shade.next();
            }
          }
        }
        pixels += x_end - x_begin;
      }

      if constexpr (kScanlineLevel) {
        if (trace_row) {
          s.active_states.clear();
          s.active_points.clear();
          for (const ActiveEdge<Stepper>& a : active) {
            s.active_states.push_back({a.edge.id, a.at.x(), a.at.ceil_x()});
            s.active_points.push_back(
                {a.at.x(), a.edge.id,
                 gouraud ? a.at.color(a.edge, y, in.colors, grid) : setup.flat});
          }
          ScanlineStep step;
          step.triangle = in.triangle;
          step.y = y;
          step.entered = s.entered;
          step.retired = s.retired;
          step.active_edges = s.active_states;
          step.active_points = s.active_points;
          step.has_span = has_span;
          step.x_begin = x_begin;
          step.x_end = x_end;
          if (has_span && gouraud) {
            step.has_span_colors = true;
            step.span_begin = span_first;
            step.span_end = span_last;
          }
          tracer.scanline(step);
        }
      }
      l.advance();
      r.advance();
      for (std::size_t i = n_active >= 2 ? 1 : 0; i + 1 < n_active; ++i) active[i].at.advance();
      if (n_active == 1) active[0].at.advance();
      if (y == run_last) break;
      if constexpr (kScanlineLevel) {
        trace_row = setup.traced && tracer.wants_scanline(in.triangle, y + 1);
        if (trace_row) s.entered.clear(), s.retired.clear();
      }
    }
    if (n_active >= 2) active.front().at = l, active.back().at = r;
    ++y;
  }
  return FillResult{SkipReason::none, rows, pixels};
}

}  // namespace detail

// Fills one convex polygon (a triangle being the common case) with the method of `opt`.
template <Canvas C, FillTracer Tracer = NoTracer>
FillResult fill_polygon(C& canvas, const PolygonInput& in, const FillOptions& opt, FillScratch& s,
                        Tracer& tracer) {
  constexpr bool kTriangleLevel = kTraceHooks && Tracer::max_level >= TraceLevel::triangle;
  [[maybe_unused]] bool traced = false;
  if constexpr (kTriangleLevel) traced = tracer.wants_triangle(in.triangle);

  auto skip = [&](SkipReason reason) {
    if constexpr (kTriangleLevel)
      if (traced) tracer.triangle_skipped(in.triangle, reason);
    return FillResult{reason, 0, 0};
  };

  const SubpixelGrid grid(opt.subpixel_bits);
  if (!grid.valid())
    throw std::invalid_argument("fill: subpixel_bits must be in 0…" +
                                std::to_string(kMaxSubpixelBits));
  const std::size_t n = in.points.size();
  if (in.colors.size() != n) throw std::invalid_argument("fill: one colour per vertex is needed");
  if (n < 3) return skip(SkipReason::too_few_vertices);
  s.snapped.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!SubpixelGrid::representable(in.points[i])) return skip(SkipReason::out_of_range);
    s.snapped[i] = grid.snap(in.points[i]);
  }
  const std::span<const FixedPoint> pts(s.snapped);
  // A zero-area polygon has no interior; under the top-left rule it owns no pixel, and the closed
  // rule is defined here for polygons with an interior too, so both skip it.
  const i128 area2 = detail::twice_area(pts);
  if (area2 == 0) return skip(SkipReason::degenerate);
  // Culling on the exact sign: a front face has negative twice_area on the y-down canvas
  // (fill_options.hpp, Cull).
  if (opt.cull != Cull::none && (opt.cull == Cull::back ? area2 > 0 : area2 < 0))
    return skip(SkipReason::culled);

  const bool closed = opt.fill_rule == FillRule::closed;
  {
    i64 x_min = pts[0].x, x_max = pts[0].x, y_min = pts[0].y, y_max = pts[0].y;
    for (const FixedPoint& p : pts) {
      x_min = std::min(x_min, p.x), x_max = std::max(x_max, p.x);
      y_min = std::min(y_min, p.y), y_max = std::max(y_max, p.y);
    }
    // The pixel rows and columns the bounding box spans under the fill rule, before clipping.
    const i64 col_first = grid.ceil_to_pixel(x_min), row_first = grid.ceil_to_pixel(y_min);
    const i64 col_last = closed ? grid.floor_to_pixel(x_max) : grid.ceil_to_pixel(x_max) - 1;
    const i64 row_last = closed ? grid.floor_to_pixel(y_max) : grid.ceil_to_pixel(y_max) - 1;
    if (col_first > col_last || row_first > row_last) return skip(SkipReason::no_pixel_centre);
    const RowBand band = canvas_rows(canvas);
    if (col_last < 0 || col_first >= canvas.width() || row_last < band.begin ||
        row_first >= band.end)
      return skip(SkipReason::offscreen);
  }

  // The flat colour is needed to fill flat, and to narrate (triangle_begin reports it); an
  // untraced Gouraud fill never reads it, so it does not pay for it.
  const Color flat = opt.shading == Shading::flat || traced
                         ? detail::mean_color(pts, in.colors, s.order)
                         : Color{};
  if constexpr (kTriangleLevel)
    if (traced)
      tracer.triangle_begin(PolygonSetup{.triangle = in.triangle,
                                         .vertices = in.points,
                                         .snapped = pts,
                                         .colors = in.colors,
                                         .depth = in.depth,
                                         .flat_color = flat,
                                         .options = &opt,
                                         .grid = grid,
                                         .vertex_depths = in.vertex_depths});

  FillResult result;
  if (opt.method == Method::halfspace) {
    result = fill_halfspace(canvas, pts, in.colors, opt, flat);
  } else {
    s.table.build(pts, grid, opt.fill_rule);
    if constexpr (kTriangleLevel)
      if (traced) tracer.edge_table(EdgeTableView{in.triangle, &s.table, pts, grid});
    const bool uniform =
        opt.shading == Shading::gouraud && std::all_of(in.colors.begin() + 1, in.colors.end(),
                                                       [&](Color c) { return c == in.colors[0]; });
    const detail::Setup setup{grid, uniform ? in.colors[0] : flat, traced, uniform};
    switch (opt.method) {
      case Method::float32:
        result = detail::sweep<FloatStepper>(canvas, in, opt, s, tracer, setup);
        break;
      case Method::double64:
        result = detail::sweep<DoubleStepper>(canvas, in, opt, s, tracer, setup);
        break;
      default:
        result = detail::sweep<ExactStepper>(canvas, in, opt, s, tracer, setup);
    }
  }
  if constexpr (kTriangleLevel)
    if (traced) tracer.triangle_end(in.triangle, result.rows, result.pixels);
  return result;
}

template <Canvas C>
FillResult fill_polygon(C& canvas, const PolygonInput& in, const FillOptions& opt, FillScratch& s) {
  NoTracer none;
  return fill_polygon(canvas, in, opt, s, none);
}

// Convenience entry points for one polygon or triangle on an image.
template <class P, class Tracer = NoTracer>
requires FillTracer<std::remove_cvref_t<Tracer>> FillResult
fill_convex_polygon(Image<P>& image, std::span<const Vec2> points, std::span<const Color> colors,
                    const FillOptions& opt = {}, Tracer&& tracer = NoTracer{}) {
  ImageCanvas<P> canvas(image);
  FillScratch scratch;
  return fill_polygon(canvas, PolygonInput{points, colors, 0, std::nullopt}, opt, scratch, tracer);
}

template <class P, class Tracer = NoTracer>
requires FillTracer<std::remove_cvref_t<Tracer>> FillResult
fill_triangle(Image<P>& image, const std::array<Vec2, 3>& v, const std::array<Color, 3>& c,
              const FillOptions& opt = {}, Tracer&& tracer = NoTracer{}) {
  return fill_convex_polygon(image, std::span<const Vec2>(v), std::span<const Color>(c), opt,
                             std::forward<Tracer>(tracer));
}

}  // namespace scantrace
