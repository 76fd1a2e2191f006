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
// and their edges follow from its vertices sorted by y (triangle_sweep.hpp), and the same convex
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
#include "flat_span.hpp"
#include "halfspace_fill.hpp"
#include "occlusion_canvas.hpp"
#include "row_cursor.hpp"
#include "row_rule.hpp"
#include "row_trace.hpp"
#include "scanline_sweep.hpp"
#include "small_triangle.hpp"
#include "span.hpp"
#include "tracer.hpp"
#include "triangle_sweep.hpp"
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
  // A triangle's is one cross product of two edges: two 64×64 → 128-bit multiplies, where the
  // shoelace sum below takes six and the loop (~64 instructions a face on the course scene).
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
  // Inlined: called, its colours went by value on the stack, stored 8 bytes at a time and loaded
  // 16 at a time, which the store buffer cannot forward (perf: a fifth of the Gouraud sweep's
  // samples on that load once the sweep had grown enough for GCC to stop inlining this).
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
//
// Within a run the outermost edges' steppers live in local variables: the canvas is written
// through byte pointers, which may alias anything, so steppers kept in the list would be reloaded
// and stored around every span. Every row of a run is then the same few steps: two ceilings, one
// span and two increments.
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

  // Inlined into the sweep (scanline_sweep.hpp says why): the list's outermost steppers, copied
  // out for the run and back after it.
  [[gnu::always_inline]] void run(i64 y, const i64 run_last, ActiveEdgeList<Stepper>& active) {
    const bool two = active.size() >= 2;
    Stepper l = two ? active.front().at : Stepper{};
    Stepper r = two ? active.back().at : Stepper{};
    run(y, run_last, active, l, r);
    if (two) active.front().at = l, active.back().at = r;
  }

  // A run whose outermost steppers the caller holds (the list's first and last edges, at row y):
  // they come back stepped past run_last, and the list's copies are written only on traced rows,
  // for the tracer. The triangle sweep holds its two so. Why: it read its long edge's stepper
  // back from the list, where the run had just stored it, and that copy loaded 16 bytes at a time
  // what the run had stored 8 bytes at a time, which the store buffer cannot forward: perf put
  // 13% of a Gouraud float64 render's sweep samples on that load (the course scene).
  [[gnu::always_inline]] void run(i64 y, const i64 run_last, ActiveEdgeList<Stepper>& active,
                                  Stepper& l_held, Stepper& r_held) {
    const bool closed = opt.fill_rule == FillRule::closed;
    const bool gouraud = opt.shading == Shading::gouraud;
    const bool shade = gouraud && !uniform;
    const int width = canvas.width();
    RowCursor<C> at(canvas, y);
    const std::size_t n_active = active.size();
    const Edge* left = n_active >= 2 ? &active.front().edge : nullptr;
    const Edge* right = n_active >= 2 ? &active.back().edge : nullptr;
    Stepper l = l_held, r = r_held;
    RunEdgeColor<Stepper> l_color, r_color;
    if (shade && left) {
      l_color.start(*left, colors, grid);
      r_color.start(*right, colors, grid);
    }
    rows += run_last - y + 1;
    i64 written = 0;  // a local, not `pixels`: a member would be reloaded after each byte store
    for (;; ++y) {
      const bool trace_row = trace.row();
      if (trace_row && n_active >= 2) active.front().at = l, active.back().at = r;
      // Under the top-left rule exactly two edges are active; the closed rule can add the two
      // edges meeting at a vertex that lies exactly on the row.
      Span span;
      if (left) {
        span.x_begin = std::max<i64>(l.ceil_x(), 0);
        // Half-open span [ceil(xl), ceil(xr)): a centre exactly on the right edge belongs to the
        // neighbour on the right. The closed rule includes it: [ceil(xl), floor(xr)].
        span.x_end = std::min<i64>(closed ? r.floor_x() + 1 : r.ceil_x(), width);
      }
      const bool has_span = !span.empty();
      Color c_left = flat, c_right = flat;
      if (left && (shade || trace_row)) {
        span.x_left = l.x();
        span.x_right = r.x();
        if (shade) {
          c_left = l_color.at(l, *left, y, colors, grid);
          c_right = r_color.at(r, *right, y, colors, grid);
        }
      }
      span.begin = span.end = flat;
      const int yi = static_cast<int>(y), xb = static_cast<int>(span.x_begin),
                xe = static_cast<int>(span.x_end);
      // The near-to-far render (occlusion_canvas.hpp): a Gouraud span all covered by nearer faces
      // costs neither its colours nor a store (a flat one is clipped by claim() alone). It still
      // counts in `written`, the pixels the face owns.
      bool hidden = false;
      if constexpr (CoverageCanvas<C>)
        hidden = shade && has_span && at.clip && CoverageMask::covered(at.cover, xb, xe);
      if (has_span && !hidden) {
        const bool trace_pixels = trace.pixels(y);
        if (!shade) {
          at.fill_flat(canvas, flat_row, flat_pixel, flat, yi, xb, xe);
          if (trace_pixels)
            for (int x = xb; x < xe; ++x) trace.pixel(canvas, x, y, flat, span.weight(x));
        } else {
          SpanShader<Stepper> shader(c_left, c_right, span.x_left, span.x_right, span.x_begin);
          // The exact method's span is linear from its first pixel's colour, so an image canvas
          // writes it in its pixel format's fastest way (whether the row is traced or not, so that
          // tracing never changes a pixel); the loop below then only narrates.
          constexpr bool kCanvasShades = DirectCanvas<C> && std::is_same_v<Stepper, ExactStepper>;
          if constexpr (kCanvasShades && CoverageCanvas<C>) {
            if (at.clip) {
              ShadedSpan<DirectPixel<C>> part(xb, xe, shader.c, shader.step);
              // Inlined as the flat run writer is (RowCursor::fill_flat): called, it was a
              // fifth of the Gouraud sweep's samples once the sweep had grown.
              const auto run = [&](int a, int b) __attribute__((always_inline)) {
                part.write(at.row, a, b);
              };
              at.claimed += CoverageMask::claim(at.cover, xb, xe, run);
            } else {
              CoverageMask::mark(at.cover, xb, xe);
              at.claimed += xe - xb;
              shade_pixels(at.row, xb, xe, shader.c, shader.step);
            }
          } else if constexpr (kCanvasShades) {
            shade_pixels(at.row, xb, xe, shader.c, shader.step);
          }
          if (trace_row) span.begin = shader.color();
          if (!kCanvasShades || trace_row) {
            for (int x = xb; x < xe; ++x) {
              const Color c = shader.color();
              if constexpr (!kCanvasShades) canvas.set(x, yi, c);
              if (trace_pixels) trace.pixel(canvas, x, y, c, span.weight(x));
              if (trace_row) span.end = c;
              shader.next();
            }
          }
        }
      }
      if (has_span) written += span.size();
      span.has_colors = has_span && gouraud;
      trace.end_row(y, active, colors, grid, gouraud, flat, false, has_span, span, false);
      l.advance();
      r.advance();
      for (std::size_t i = n_active >= 2 ? 1 : 0; i + 1 < n_active; ++i) active[i].at.advance();
      if (n_active == 1) active[0].at.advance();
      if (y == run_last) break;
      at.next_row();
      trace.begin_row(y + 1);
    }
    l_held = l, r_held = r;
    pixels += written;
    at.finish(canvas);
  }
};

// A small triangle of one colour (small_triangle.hpp): its rows' spans from the SIMD kernel,
// written as the convex rule writes a flat span, and the same counts.
template <Canvas C>
FillResult fill_small_triangle(C& canvas, const SmallTriangle& t, Color color, FlatRow& flat_row) {
  // The pixel first, the spans after: the rows read the pixel from memory (RowCursor::fill_flat
  // takes it by reference), and the kernel's call between its stores and their first load lets
  // them reach the cache. Made after the kernel, the pixel was stored a few instructions before
  // the first row loaded it, in wider loads than its stores, which the store buffer cannot
  // forward: a stall on every face, half of a near-to-far float64 render's samples in this
  // function (perf, the course scene).
  DirectPixel<C> pixel{};
  if constexpr (DirectCanvas<C>) pixel = C::convert(color);
  std::array<RowSpan, kSmallTriangleRows> spans;  // only rows [0, t.rows) are written and read
  small_triangle_spans(t, spans.data());
  RowCursor<C> at(canvas, t.row0);
  i64 pixels = 0;
  for (int r = 0;;) {
    const RowSpan span = spans[r];
    if (span.begin < span.end) {
      at.fill_flat(canvas, flat_row, pixel, color, t.row0 + r, span.begin, span.end);
      pixels += span.end - span.begin;
    }
    if (++r == t.rows) break;
    at.next_row();
  }
  at.finish(canvas);
  return {SkipReason::none, t.rows, pixels};
}

}  // namespace detail

// Fills one convex polygon (a triangle being the common case) with the method of `opt`.
template <Canvas C, FillTracer Tracer = NoTracer>
FillResult fill_polygon(C& canvas, const PolygonInput& in, const FillOptions& opt, FillScratch& s,
                        Tracer& tracer) {
  constexpr bool kTriangleLevel = kTraceHooks && Tracer::max_level >= TraceLevel::triangle;
  [[maybe_unused]] bool traced = false;
  if constexpr (kTriangleLevel) traced = tracer.wants_triangle(in.face);

  auto skip = [&](SkipReason reason) {
    if constexpr (kTriangleLevel)
      if (traced) tracer.triangle_skipped(in.face, reason);
    return FillResult{reason, 0, 0};
  };

  const SubpixelGrid grid(opt.subpixel_bits);
  require_valid(grid);
  if (const SkipReason r = snap_vertices(in.points, in.colors, grid, s.snapped);
      r != SkipReason::none)
    return skip(r);
  const std::span<const FixedPoint> pts(s.snapped);
  // A zero-area polygon has no interior; under the top-left rule it owns no pixel, and the closed
  // rule is defined here for polygons with an interior too, so both skip it.
  const i128 area2 = detail::twice_area(pts);
  if (area2 == 0) return skip(SkipReason::degenerate);
  // Culling on the exact sign: a front face has negative twice_area on the y-down canvas
  // (fill_options.hpp, Cull).
  if (opt.cull != Cull::none && (opt.cull == Cull::back ? area2 > 0 : area2 < 0))
    return skip(SkipReason::culled);

  const GridBox box = grid_box(pts, grid, opt.fill_rule);
  if (const SkipReason r = covers_pixels(box, canvas.width(), canvas_rows(canvas));
      r != SkipReason::none)
    return skip(r);

  // The flat colour is needed to fill flat, and to narrate (triangle_begin reports it); an
  // untraced Gouraud fill never reads it, so it does not pay for it.
  const Color flat =
      opt.shading == Shading::flat || traced ? flat_color(pts, in.colors, s.order) : Color{};
  if constexpr (kTriangleLevel)
    if (traced)
      tracer.triangle_begin(PolygonSetup{.face = in.face,
                                         .vertices = in.points,
                                         .snapped = pts,
                                         .colors = in.colors,
                                         .depth = in.depth,
                                         .flat_color = flat,
                                         .options = &opt,
                                         .grid = grid,
                                         .vertex_depths = in.vertex_depths});

  // An untraced triangle of the exact method under the top-left rule needs no edge table
  // (triangle_sweep.hpp), and a small one of one colour not even its edges (small_triangle.hpp);
  // everything else is swept from its table.
  const bool triangle = pts.size() == 3 && opt.method == Method::exact &&
                        opt.fill_rule == FillRule::top_left && !traced;
  const bool uniform =
      opt.shading == Shading::gouraud && std::all_of(in.colors.begin() + 1, in.colors.end(),
                                                     [&](Color c) { return c == in.colors[0]; });
  const Color fill_color = uniform ? in.colors[0] : flat;
  FillResult result;
  SmallTriangle small;
  if (opt.method == Method::halfspace) {
    result = fill_halfspace(canvas, pts, in.colors, opt, flat);
  } else if (triangle && (opt.shading == Shading::flat || uniform) &&
             small_triangle(pts, box, area2 > 0, grid, canvas.width(), canvas_rows(canvas),
                            small)) {
    result = detail::fill_small_triangle(canvas, small, fill_color, s.flat_row);
  } else {
    if (!triangle) s.table.build(pts, grid, opt.fill_rule);
    if constexpr (kTriangleLevel)
      if (traced) tracer.edge_table(EdgeTableView{in.face, &s.table, pts, grid});
    RowTrace<Tracer> trace(tracer, s.trace, in.face, traced);
    result = with_stepper(opt.method, [&]<class Stepper>() {
      detail::ConvexRows<Stepper, C, Tracer> rule{
          {canvas, in.colors, grid, opt, fill_color, trace}, uniform, s.flat_row};
      if constexpr (DirectCanvas<C>)
        if (opt.shading == Shading::flat || uniform) rule.flat_pixel = C::convert(fill_color);
      if constexpr (std::is_same_v<Stepper, ExactStepper>)
        if (triangle) {
          sweep_triangle(pts, canvas_rows(canvas), grid, in.colors, s.active_exact, rule);
          return rule.result();
        }
      sweep_scanlines(s.table, canvas_rows(canvas), grid, in.colors, s.active<Stepper>(), rule);
      return rule.result();
    });
  }
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
