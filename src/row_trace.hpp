#pragma once
// The tracer as a consumer of the sweep's rows (tracer.hpp): which rows and pixels it wants, the
// edges that entered and retired, and the ScanlineStep it is shown once a row is written. Both
// fills narrate through this one piece; with a tracer whose max_level is below `scanline` every
// member compiles to nothing.
#include <span>
#include <vector>

#include "active_edge_list.hpp"
#include "depth_test.hpp"
#include "span.hpp"
#include "tracer.hpp"

namespace scantrace {

// What narrating rows needs, reusable across polygons (part of the fills' scratch).
struct RowTraceScratch {
  std::vector<int> entered, retired;
  std::vector<EdgeCrossing> active_states;
  std::vector<ActivePoint> active_points;
  std::vector<Span> spans;
};

// The colour the trace reports at each active point: the edge's colour at the row (Gouraud) or the
// polygon's one colour (flat).
struct PointColors {
  std::span<const Color> colors;  // one per vertex
  const SubpixelGrid& grid;
  bool gouraud;
  Color flat;

  template <class Stepper>
  Color at(const ActiveEdge<Stepper>& a, i64 y) const {
    return gouraud ? a.at.color(a.edge, y, colors, grid) : flat;
  }
};

template <class Tracer>
class RowTrace {
 public:
  static constexpr bool kRows = kTraceHooks && Tracer::max_level >= TraceLevel::scanline;
  static constexpr bool kPixels = kTraceHooks && Tracer::max_level >= TraceLevel::pixel;

  // `traced`: the tracer wants this polygon at all (wants_triangle).
  RowTrace(Tracer& tracer, RowTraceScratch& s, int face, bool traced)
      : tracer_(tracer), s_(s), face_(face), traced_(traced) {}

  // Decides whether row y is narrated; called before anything happens on the row.
  void begin_row(i64 y) {
    if constexpr (kRows) {
      row_ = traced_ && tracer_.wants_scanline(face_, y);
      if (row_) s_.entered.clear(), s_.retired.clear(), s_.spans.clear();
    }
  }
  bool row() const { return kRows && row_; }
  bool pixels(i64 y) {
    if constexpr (kPixels) return row_ && tracer_.wants_pixels(face_, y);
    return false;
  }
  void entered(const Edge& e) {
    if constexpr (kRows)
      if (row_) s_.entered.push_back(e.id);
  }
  void retired(const Edge& e) {
    if constexpr (kRows)
      if (row_) s_.retired.push_back(e.id);
  }
  // A span of a general polygon, kept for the row's step.
  void span(const Span& sp) {
    if constexpr (kRows)
      if (row_) s_.spans.push_back(sp);
  }

  // One pixel, with the outcome of its depth test when the canvas tests depth and the tracer takes
  // it (the canvas has just written the pixel: a span's pixels are narrated right after it).
  template <class C>
  void pixel(const C& canvas, int x, i64 y, Color c, double t) {
    if constexpr (kPixels) {
      if constexpr (DepthTestingCanvas<C> &&
                    requires { tracer_.pixel(face_, x, y, c, t, canvas.depth_test(x)); })
        tracer_.pixel(face_, x, y, c, t, canvas.depth_test(x));
      else
        tracer_.pixel(face_, x, y, c, t);
    }
  }

  // The row of a convex polygon is written: show the tracer its active edge list and its span
  // (`span` null when the row has none).
  template <class Stepper>
  void end_convex_row(i64 y, const ActiveEdgeList<Stepper>& active, const PointColors& points,
                      const Span* span) {
    if constexpr (kRows)
      if (row_) end_row(y, active, points, /*windings=*/false, span);
  }

  // The row of a general polygon is written: its active edges with their windings, and the spans
  // kept by span() (its intervals).
  template <class Stepper>
  void end_winding_row(i64 y, const ActiveEdgeList<Stepper>& active, const PointColors& points) {
    if constexpr (kRows)
      if (row_) end_row(y, active, points, /*windings=*/true, nullptr);
  }

 private:
  template <class Stepper>
  void end_row(i64 y, const ActiveEdgeList<Stepper>& active, const PointColors& points,
               bool windings, const Span* span) {
    s_.active_states.clear();
    s_.active_points.clear();
    for (const ActiveEdge<Stepper>& a : active) {
      s_.active_states.push_back(
          {a.edge.id, a.at.x(), a.at.ceil_x(), windings ? a.edge.winding() : 0});
      s_.active_points.push_back({a.at.x(), a.edge.id, points.at(a, y)});
    }
    ScanlineStep step;
    step.face = face_;
    step.y = y;
    step.entered = s_.entered;
    step.retired = s_.retired;
    step.active_edges = s_.active_states;
    step.active_points = s_.active_points;
    step.has_intervals = windings;
    step.intervals = s_.spans;
    step.has_span = windings ? !s_.spans.empty() : span != nullptr;
    if (step.has_span) step.span = windings ? s_.spans.front() : *span;
    tracer_.scanline(step);
  }

  Tracer& tracer_;
  RowTraceScratch& s_;
  int face_;
  bool traced_;
  bool row_ = false;
};

}  // namespace scantrace
