#pragma once
// The edge-table / active-edge-list scanline fill of a convex polygon (a triangle being the
// common case), flat or Gouraud, under the fill rules of docs/design.md §3.
//
//   1. snap the vertices to the subpixel grid; reject what cannot fill a pixel (degenerate,
//      off the canvas) before any per-row work (fill_setup.hpp);
//   2. build the edge table: non-horizontal edges sorted by their first scanline;
//   3. sweep the scanlines that are on the canvas (scanline_sweep.hpp) with the convex rule: a
//      convex polygon meets a row in one span, from the leftmost active crossing to the rightmost.
// An untraced triangle of the exact method under the top-left rule skips the table: its two runs
// and their edges follow from its vertices sorted by y (fast/triangle_sweep.hpp), and the same convex
// rule draws them, bit for bit as the general sweep would.
#include <algorithm>
#include <array>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "canvas.hpp"
#include "edge_stepper.hpp"
#include "edge_table.hpp"
#include "fill_options.hpp"
#include "fill_scratch.hpp"
#include "fill_setup.hpp"
#include "flat_color.hpp"
#include "fast/flat_span.hpp"
#include "halfspace_fill.hpp"
#include "fast/occlusion_canvas.hpp"
#include "fast/row_cursor.hpp"
#include "row_rule.hpp"
#include "row_trace.hpp"
#include "scanline_sweep.hpp"
#include "fast/small_triangle.hpp"
#include "span.hpp"
#include "tracer.hpp"
#include "fast/triangle_sweep.hpp"
#include "vector_interp.hpp"

namespace scantrace {

// One polygon to fill: its vertices (pixels) and one colour per vertex. `face` is the index the
// trace reports (the face's position in a scene; 0 for a polygon filled alone; format v1 calls
// it "triangle" whatever the polygon); `depth` is reported when known.
struct PolygonInput {
  std::span<const Vec2> points;
  std::span<const Color> colors;
  int face = 0;
  std::optional<double> depth;
  // Z-buffer renders: the depth of each vertex, which the trace records so that a replay can
  // redo every pixel's depth test (src/depth_plane.hpp). Empty otherwise.
  std::span<const double> vertex_depths = {};
};

namespace detail {

// Twice the signed area, exactly.
inline i128 twice_area(std::span<const FixedPoint> p) {
  // A triangle's is one cross product of two edges: two 128-bit multiplies where the shoelace
  // sum below takes six and a loop.
  if (p.size() == 3)
    return static_cast<i128>(p[1].x - p[0].x) * (p[2].y - p[0].y) -
           static_cast<i128>(p[1].y - p[0].y) * (p[2].x - p[0].x);
  i128 a = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const FixedPoint u = p[i], v = p[i + 1 == n ? 0 : i + 1];
    a += static_cast<i128>(u.x) * v.y - static_cast<i128>(v.x) * u.y;
  }
  return a;
}

// Colours along one span, the way each method computes them.
template <class Stepper>
struct SpanShader {
  // exact: the course's linear interpolation along x, as one reciprocal per span (a division per
  // span, not per pixel) and one increment per pixel in double: the colour is linear along the
  // row, and 16,384 increments drift by ~1e-12, far inside the 1e-4 budget.
  Color c, step;
  // Inlined: called, its colours pass through the stack in stores the next loads cannot be
  // forwarded from (docs/performance.md, "Why the fast code looks as it does").
  [[gnu::always_inline]] SpanShader(Color left, Color right, double xl, double xr, i64 x_begin) {
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

// The convex rule of the sweep (scanline_sweep.hpp): on each row one span, from the leftmost
// active crossing to the rightmost, written to the canvas and narrated to the tracer.
template <class Stepper, Canvas C, FillTracer Tracer>
struct ConvexRows : RowRule<C, Tracer> {
  using RowRule<C, Tracer>::canvas, RowRule<C, Tracer>::colors, RowRule<C, Tracer>::grid,
      RowRule<C, Tracer>::opt, RowRule<C, Tracer>::flat, RowRule<C, Tracer>::trace,
      RowRule<C, Tracer>::rows, RowRule<C, Tracer>::pixels;
  // Gouraud with equal colours gives the same colour everywhere: such a polygon is filled as a
  // flat one (the trace still reports Gouraud span colours, which are that colour).
  bool uniform = false;
  FlatRow& flat_row;
  // The flat colour in the canvas's pixel format, converted once per polygon (DirectCanvas only).
  DirectPixel<C> flat_pixel{};

  // What every row of a run reads, copied into locals: the canvas is written through byte
  // pointers, which may alias the rule's members, so a member read per row is reloaded per row.
  struct RunConstants {
    bool closed;   // the closed fill rule (else top-left)
    bool gouraud;  // the spans report colours
    bool shade;    // the spans are written in interpolated colours (Gouraud, not uniform)
    int width;
  };

  // Inlined into the sweep (scanline_sweep.hpp says why): the list's outermost steppers, copied
  // out for the run and back after it.
  [[gnu::always_inline]] void run(i64 y, const i64 run_last, ActiveEdgeList<Stepper>& active) {
    const bool two = active.size() >= 2;
    Stepper l = two ? active.front().at : Stepper{};
    Stepper r = two ? active.back().at : Stepper{};
    run(y, run_last, active, l, r);
    if (two) active.front().at = l, active.back().at = r;
  }

  // The rows y … run_last, during which the active edges do not change: on each row the span
  // between the outermost crossings, its colours, the canvas, the tracer; then every crossing
  // one row down. The caller holds the outermost steppers (the list's first and last edges, at
  // row y) and gets them back stepped past run_last: kept in locals rather than in the list, they
  // are not reloaded and stored around every span (docs/performance.md, "Why the fast code looks
  // as it does").
  [[gnu::always_inline]] void run(i64 y, const i64 run_last, ActiveEdgeList<Stepper>& active,
                                  Stepper& l_held, Stepper& r_held) {
    const RunConstants k{opt.fill_rule == FillRule::closed, opt.shading == Shading::gouraud,
                         opt.shading == Shading::gouraud && !uniform, canvas.width()};
    const std::size_t n_active = active.size();
    const Edge* left = n_active >= 2 ? &active.front().edge : nullptr;
    const Edge* right = n_active >= 2 ? &active.back().edge : nullptr;
    Stepper l = l_held, r = r_held;
    RunEdgeColor<Stepper> l_color, r_color;
    if (k.shade && left) {
      l_color.start(*left, colors, grid);
      r_color.start(*right, colors, grid);
    }
    RowCursor<C> at(canvas, y);
    rows += run_last - y + 1;
    i64 written = 0;  // a local, not `pixels`: a member would be reloaded after each byte store
    for (;; ++y) {
      const bool trace_row = trace.row();
      if (trace_row && left) active.front().at = l, active.back().at = r;  // what the tracer reads
      Span span = left ? row_span(l, r, k) : Span{};
      Color c_left = flat, c_right = flat;
      if (left && (k.shade || trace_row)) span.x_left = l.x(), span.x_right = r.x();
      if (left && k.shade) {
        c_left = l_color.at(l, *left, y, colors, grid);
        c_right = r_color.at(r, *right, y, colors, grid);
      }
      const bool has_span = !span.empty();
      span.begin = span.end = flat;
      if (has_span) {
        write_span(at, span, c_left, c_right, y, trace_row, k);
        written += span.size();
      }
      span.has_colors = has_span && k.gouraud;
      trace.end_convex_row(y, active, PointColors{colors, grid, k.gouraud, flat},
                           has_span ? &span : nullptr);
      l.advance();
      r.advance();
      advance_inner(active, n_active);
      if (y == run_last) break;
      at.next_row();
      trace.begin_row(y + 1);
    }
    l_held = l, r_held = r;
    pixels += written;
    at.finish(canvas);
  }

  // Row y's pixels between the crossings, clipped to the canvas. Half-open [ceil(xl), ceil(xr))
  // under the top-left rule: a centre exactly on the right edge belongs to the neighbour on the
  // right. The closed rule includes it: [ceil(xl), floor(xr)].
  [[gnu::always_inline]] static Span row_span(const Stepper& l, const Stepper& r,
                                              const RunConstants& k) {
    Span span;
    span.x_begin = std::max<i64>(l.ceil_x(), 0);
    span.x_end = std::min<i64>(k.closed ? r.floor_x() + 1 : r.ceil_x(), k.width);
    return span;
  }

  // The span's pixels to the canvas, and to the tracer on a traced row (with the span's first
  // and last colours, which the row's step reports).
  [[gnu::always_inline]] void write_span(RowCursor<C>& at, Span& span, Color c_left,
                                         Color c_right, i64 y, bool trace_row,
                                         const RunConstants& k) {
    const int yi = static_cast<int>(y), xb = static_cast<int>(span.x_begin),
              xe = static_cast<int>(span.x_end);
    const bool trace_pixels = trace.pixels(y);
    if (!k.shade) {
      at.fill_flat(canvas, flat_row, flat_pixel, flat, yi, xb, xe);
      if (trace_pixels)
        for (int x = xb; x < xe; ++x) trace.pixel(canvas, x, y, flat, span.weight(x));
      return;
    }
    if (at.hidden(xb, xe)) return;  // near to far: nearer faces cover it all
    SpanShader<Stepper> shader(c_left, c_right, span.x_left, span.x_right, span.x_begin);
    // The exact method's span is linear from its first pixel's colour, so a canvas with a pixel
    // format writes it the fastest way it can, traced or not (tracing never changes a pixel); the
    // loop below then only narrates. Other canvases and methods take a colour per pixel here.
    constexpr bool kCanvasShades = DirectCanvas<C> && std::is_same_v<Stepper, ExactStepper>;
    if constexpr (kCanvasShades) {
      at.shade(xb, xe, shader.c, shader.step);
      if (!trace_row) return;
    }
    if (trace_row) span.begin = shader.color();
    for (int x = xb; x < xe; ++x) {
      const Color c = shader.color();
      if constexpr (!kCanvasShades) canvas.set(x, yi, c);
      if (trace_pixels) trace.pixel(canvas, x, y, c, span.weight(x));
      if (trace_row) span.end = c;
      shader.next();
    }
  }

  // The list's crossings other than the outermost two (held by the run) one row down. Under the
  // top-left rule there are none; the closed rule can add the two edges meeting at a vertex that
  // lies exactly on the row.
  [[gnu::always_inline]] static void advance_inner(ActiveEdgeList<Stepper>& active,
                                                   std::size_t n_active) {
    for (std::size_t i = n_active >= 2 ? 1 : 0; i + 1 < n_active; ++i) active[i].at.advance();
    if (n_active == 1) active[0].at.advance();
  }
};

// Which way a polygon is drawn. The edge table is the course's fill, and the only way a trace
// narrates; the other two draw the same pixels, bit for bit, with less work where they can
// (src/fast/): a triangle's two runs without a table, a small one-colour triangle by SIMD edge
// functions. The halfspace method is the other classic algorithm, for comparison.
enum class FillPath { edge_table, triangle_sweep, small_triangle, halfspace };

// A polygon past its set-up (fill_setup.hpp): snapped, with an interior, facing the way the
// options keep, and with a pixel centre on the canvas.
struct PreparedPolygon {
  SubpixelGrid grid;
  std::span<const FixedPoint> pts;  // snapped, in grid units
  i128 area2 = 0;                   // twice the signed area
  GridBox box{};
};

// Set-up: snap the vertices, then reject what cannot fill a pixel (docs/design.md §3).
template <Canvas C>
SkipReason prepare(const C& canvas, const PolygonInput& in, const FillOptions& opt,
                   std::vector<FixedPoint>& snapped, PreparedPolygon& p) {
  p.grid = SubpixelGrid(opt.subpixel_bits);
  require_valid(p.grid);
  if (const SkipReason r = snap_vertices(in.points, in.colors, p.grid, snapped);
      r != SkipReason::none)
    return r;
  p.pts = snapped;
  // A zero-area polygon has no interior; under the top-left rule it owns no pixel, and the closed
  // rule is defined here for polygons with an interior too, so both skip it.
  p.area2 = twice_area(p.pts);
  if (p.area2 == 0) return SkipReason::degenerate;
  // Culling on the exact sign: a front face has negative twice_area on the y-down canvas
  // (fill_options.hpp, Cull).
  if (opt.cull != Cull::none && (opt.cull == Cull::back ? p.area2 > 0 : p.area2 < 0))
    return SkipReason::culled;
  p.box = grid_box(p.pts, p.grid, opt.fill_rule);
  return covers_pixels(p.box, canvas.width(), canvas_rows(canvas));
}

// The path for a prepared polygon; `small` is set when it is FillPath::small_triangle. Only an
// untraced triangle of the exact method under the top-left rule leaves the edge table.
template <Canvas C>
FillPath choose_path(const C& canvas, const PreparedPolygon& p, const FillOptions& opt,
                     bool one_colour, bool traced, SmallTriangle& small) {
  if (opt.method == Method::halfspace) return FillPath::halfspace;
  if (p.pts.size() != 3 || opt.method != Method::exact || opt.fill_rule != FillRule::top_left ||
      traced)
    return FillPath::edge_table;
  if (one_colour && small_triangle(p.pts, p.box, p.area2 > 0, p.grid, canvas.width(),
                                   canvas_rows(canvas), small))
    return FillPath::small_triangle;
  return FillPath::triangle_sweep;
}

// The rows of a polygon by the scanline sweep: from its edge table, or (FillPath::triangle_sweep)
// from its vertices sorted by y, each row by the convex rule.
template <Canvas C, class Tracer>
FillResult sweep_polygon(C& canvas, const PolygonInput& in, const PreparedPolygon& p,
                         const FillOptions& opt, FillScratch& s, Tracer& tracer, FillPath path,
                         Color colour, bool uniform, bool traced) {
  if (path == FillPath::edge_table) s.table.build(p.pts, p.grid, opt.fill_rule);
  if constexpr (kTraceHooks && Tracer::max_level >= TraceLevel::triangle)
    if (traced) tracer.edge_table(EdgeTableView{in.face, &s.table, p.pts, p.grid});
  RowTrace<Tracer> trace(tracer, s.trace, in.face, traced);
  return with_stepper(opt.method, [&]<class Stepper>() {
    ConvexRows<Stepper, C, Tracer> rule{
        {canvas, in.colors, p.grid, opt, colour, trace}, uniform, s.flat_row};
    if constexpr (DirectCanvas<C>)
      if (opt.shading == Shading::flat || uniform) rule.flat_pixel = C::convert(colour);
    if constexpr (std::is_same_v<Stepper, ExactStepper>)
      if (path == FillPath::triangle_sweep) {
        sweep_triangle(p.pts, canvas_rows(canvas), p.grid, in.colors, s.active_exact, rule);
        return rule.result();
      }
    sweep_scanlines(s.table, canvas_rows(canvas), p.grid, in.colors, s.active<Stepper>(), rule);
    return rule.result();
  });
}

}  // namespace detail

// Fills one convex polygon (a triangle being the common case) with the method of `opt`: set-up,
// then its rows by the path chosen for it, narrated to `tracer` when it wants the polygon.
template <Canvas C, FillTracer Tracer = NoTracer>
FillResult fill_polygon(C& canvas, const PolygonInput& in, const FillOptions& opt, FillScratch& s,
                        Tracer& tracer) {
  constexpr bool kTriangleLevel = kTraceHooks && Tracer::max_level >= TraceLevel::triangle;
  [[maybe_unused]] bool traced = false;
  if constexpr (kTriangleLevel) traced = tracer.wants_triangle(in.face);

  detail::PreparedPolygon p;
  if (const SkipReason r = detail::prepare(canvas, in, opt, s.snapped, p); r != SkipReason::none) {
    if constexpr (kTriangleLevel)
      if (traced) tracer.triangle_skipped(in.face, r);
    return FillResult{r, 0, 0};
  }
  // The flat colour is needed to fill flat, and to narrate (triangle_begin reports it); an
  // untraced Gouraud fill never reads it, so it does not pay for it.
  const Color flat =
      opt.shading == Shading::flat || traced ? flat_color(p.pts, in.colors, s.order) : Color{};
  if constexpr (kTriangleLevel)
    if (traced)
      tracer.triangle_begin(PolygonSetup{.face = in.face,
                                         .vertices = in.points,
                                         .snapped = p.pts,
                                         .colors = in.colors,
                                         .depth = in.depth,
                                         .flat_color = flat,
                                         .options = &opt,
                                         .grid = p.grid,
                                         .vertex_depths = in.vertex_depths});

  const bool uniform =
      opt.shading == Shading::gouraud && std::all_of(in.colors.begin() + 1, in.colors.end(),
                                                     [&](Color c) { return c == in.colors[0]; });
  const Color colour = uniform ? in.colors[0] : flat;
  SmallTriangle small;
  const detail::FillPath path = detail::choose_path(
      canvas, p, opt, opt.shading == Shading::flat || uniform, traced, small);
  FillResult result;
  if (path == detail::FillPath::halfspace)
    result = fill_halfspace(canvas, p.pts, in.colors, opt, flat);
  else if (path == detail::FillPath::small_triangle)
    result = fill_small_triangle(canvas, small, colour, s.flat_row);
  else
    result = detail::sweep_polygon(canvas, in, p, opt, s, tracer, path, colour, uniform, traced);
  if constexpr (kTriangleLevel)
    if (traced) tracer.triangle_end(in.face, result.rows, result.pixels);
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
