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
// Pixel ownership generalises the top-left rule of docs/design.md §3. A pixel centre (x, y) is
// inside iff the winding rule holds for the edges crossing row y at x_c <= x, where an edge crosses
// row y iff y_top <= y < y_bottom. That is the winding at the centre moved down by an infinitesimal
// δ and right by an infinitesimal ε >> δ. So an interval between crossings x_L and x_R owns the
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
#include <type_traits>
#include <vector>

#include "canvas.hpp"
#include "edge_stepper.hpp"
#include "edge_table.hpp"
#include "fill_options.hpp"
#include "fill_result.hpp"
#include "fill_scratch.hpp"
#include "fill_setup.hpp"
#include "flat_color.hpp"
#include "row_rule.hpp"
#include "row_trace.hpp"
#include "scanline_sweep.hpp"
#include "span.hpp"
#include "tracer.hpp"

namespace scantrace {

namespace winding_detail {

inline bool inside(int winding, WindingRule rule) {
  return rule == WindingRule::even_odd ? (winding & 1) != 0 : winding != 0;
}

// The winding rule of the sweep (scanline_sweep.hpp): on each row, the active list re-sorted by
// exact x, its windings summed left to right, one span per interval the rule puts inside.
template <class Stepper, Canvas C, FillTracer Tracer>
struct WindingRows : RowRule<C, Tracer> {
  using RowRule<C, Tracer>::canvas, RowRule<C, Tracer>::colors, RowRule<C, Tracer>::grid,
      RowRule<C, Tracer>::opt, RowRule<C, Tracer>::flat, RowRule<C, Tracer>::trace,
      RowRule<C, Tracer>::rows, RowRule<C, Tracer>::pixels;

  void run(i64 y, const i64 last, ActiveEdgeList<Stepper>& active) {
    const bool gouraud = opt.shading == Shading::gouraud;
    for (;; ++y) {
      // Edges may cross one another between rows, even within a run: only those move.
      active.sort_by_x();
      ++rows;
      spans(y, active);
      trace.end_winding_row(y, active, PointColors{colors, grid, gouraud, flat});
      active.advance();
      if (y == last) return;
      trace.begin_row(y + 1);
    }
  }

  // The row's crossings → its inside intervals → spans, written and narrated.
  void spans(i64 y, const ActiveEdgeList<Stepper>& active) {
    const bool gouraud = opt.shading == Shading::gouraud;
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
      Span sp;
      sp.x_begin = std::max<i64>(l.at.ceil_x(), 0);
      sp.x_end = std::min<i64>(a.at.ceil_x(), canvas.width());
      if (sp.empty()) continue;
      sp.left_edge = l.edge.id, sp.right_edge = a.edge.id;
      sp.x_left = l.at.x(), sp.x_right = a.at.x();
      sp.has_colors = gouraud;
      sp.begin = sp.end = flat;
      const int yi = static_cast<int>(y), xb = static_cast<int>(sp.x_begin),
                xe = static_cast<int>(sp.x_end);
      const bool trace_pixels = trace.pixels(y);
      if (!gouraud) {
        canvas.fill_span(yi, xb, xe, flat);
        if (trace_pixels)
          for (int x = xb; x < xe; ++x) trace.pixel(canvas, x, y, flat, sp.weight(x));
      } else {
        // Each pixel evaluated from the interval's end colours: nothing accumulates along a long
        // interval, and it costs one multiply-add per channel.
        const Color cl = l.at.color(l.edge, y, colors, grid);
        const Color cr = a.at.color(a.edge, y, colors, grid);
        const double xl = sp.x_left, xr = sp.x_right;
        const Color slope = xr > xl ? (cr - cl) * (1.0 / (xr - xl)) : Color{};
        for (int x = xb; x < xe; ++x) {
          const Color c = cl + slope * (x - xl);
          canvas.set(x, yi, c);
          if (trace_pixels) trace.pixel(canvas, x, y, c, sp.weight(x));
          if (trace.row()) {
            if (x == xb) sp.begin = c;
            sp.end = c;
          }
        }
      }
      pixels += sp.size();
      trace.span(sp);
    }
  }
};

}  // namespace winding_detail

// Fills the polygon whose closed contours are `contours` (each a list of vertices in pixels;
// holes are just more contours — under non-zero they must run the other way round to be holes),
// with one colour per vertex in `colors`, the contours' vertices one after another. Edge i of the
// trace runs from vertex i (in that global numbering) to the next vertex of its contour.
// `face` is the index the trace reports. Methods exact (default), double and float; the
// halfspace method and the closed fill rule are convex-only and rejected.
template <Canvas C, FillTracer Tracer = NoTracer>
FillResult fill_polygon_contours(C& canvas, std::span<const std::vector<Vec2>> contours,
                                 std::span<const Color> colors, const FillOptions& opt,
                                 WindingScratch& s, Tracer& tracer, int face = 0) {
  constexpr bool kTriangleLevel = kTraceHooks && Tracer::max_level >= TraceLevel::triangle;
  [[maybe_unused]] bool traced = false;
  if constexpr (kTriangleLevel) traced = tracer.wants_triangle(face);
  auto skip = [&](SkipReason reason) {
    if constexpr (kTriangleLevel)
      if (traced) tracer.triangle_skipped(face, reason);
    return FillResult{reason, 0, 0};
  };

  const SubpixelGrid grid(opt.subpixel_bits);
  require_valid(grid);
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
  if (const SkipReason r = snap_vertices(s.points, colors, grid, s.snapped); r != SkipReason::none)
    return skip(r);
  if (const SkipReason r = covers_pixels(grid_box(s.snapped, grid, FillRule::top_left),
                                         canvas.width(), canvas_rows(canvas));
      r != SkipReason::none)
    return skip(r);
  const Color flat =
      opt.shading == Shading::flat || traced ? flat_color(s.snapped, colors, s.order) : Color{};
  if constexpr (kTriangleLevel)
    if (traced) {
      PolygonSetup setup{face, s.points, s.snapped, colors, std::nullopt, flat, &opt, grid};
      setup.contour_sizes = s.sizes;
      tracer.triangle_begin(setup);
    }
  s.table.build_contours(s.snapped, s.sizes, grid, FillRule::top_left);
  if constexpr (kTriangleLevel)
    if (traced) tracer.edge_table(EdgeTableView{face, &s.table, s.snapped, grid});
  RowTrace<Tracer> trace(tracer, s.trace, face, traced);
  const FillResult result = with_stepper(opt.method, [&]<class Stepper>() {
    winding_detail::WindingRows<Stepper, C, Tracer> rule{{canvas, colors, grid, opt, flat, trace}};
    sweep_scanlines(s.table, canvas_rows(canvas), grid, colors, s.active<Stepper>(), rule);
    return rule.result();
  });
  if constexpr (kTriangleLevel)
    if (traced) tracer.triangle_end(face, result.rows, result.pixels);
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
