#include "event_tracer.hpp"

namespace scantrace::trace {

Header make_header(int width, int height, const FillOptions& options, TraceLevel level) {
  Header h;
  h.canvas = {width, height};
  h.shading = options.shading;
  h.fill_rule = options.fill_rule;
  h.subpixel_bits = options.subpixel_bits;
  h.level = level;
  h.generator = std::string("scantrace ") + SCANTRACE_VERSION;
  h.visibility = options.visibility;
  h.cull = options.cull;
  return h;
}

TriangleBegin to_event(const PolygonSetup& s) {
  TriangleBegin e;
  e.triangle = s.face;
  e.vertices.assign(s.vertices.begin(), s.vertices.end());
  for (const FixedPoint& p : s.snapped) e.snapped.push_back(s.grid.to_pixels(p));
  e.colors.assign(s.colors.begin(), s.colors.end());
  e.depth = s.depth;
  e.vertex_depths.assign(s.vertex_depths.begin(), s.vertex_depths.end());
  if (s.options->shading == Shading::flat) e.flat_color = s.flat_color;
  int next = 0;
  for (const int size : s.contour_sizes) {
    std::vector<int>& c = e.contours.emplace_back();
    for (int k = 0; k < size; ++k) c.push_back(next++);
  }
  return e;
}

EdgeTableEvent to_event(const EdgeTableView& v) {
  EdgeTableEvent t;
  t.triangle = v.face;
  for (const Edge& e : v.table->edges()) {
    EdgeEntry x;
    x.edge = e.id;
    // The edge runs from vertex `id` to its other endpoint — the next vertex of its contour,
    // which is (id + 1) mod n only for a polygon of one contour.
    x.from = v.grid.to_pixels(v.snapped[e.id]);
    x.to = v.grid.to_pixels(v.snapped[e.top == e.id ? e.bottom : e.top]);
    const Vec2 top = v.grid.to_pixels(e.p_top), bottom = v.grid.to_pixels(e.p_bottom);
    x.y_min = top.y;
    x.y_max = bottom.y;
    x.x_at_y_min = top.x;
    x.dx_dy = static_cast<double>(e.dx()) / static_cast<double>(e.dy());
    x.first_row = e.first_row;
    x.last_row = e.last_row;
    t.edges.push_back(x);
  }
  for (const HorizontalEdge& h : v.table->horizontal())
    t.horizontal.push_back({h.id, v.grid.to_pixels(v.snapped[h.from]),
                            v.grid.to_pixels(v.snapped[h.to]),
                            static_cast<double>(h.y) / static_cast<double>(v.grid.scale()),
                            "horizontal: it lies along one row and never crosses a scanline; the "
                            "fill rule decides its row through the neighbouring edges"});
  return t;
}

Scanline to_event(const ScanlineStep& s) {
  Scanline e;
  e.triangle = s.face;
  e.y = s.y;
  e.entered.assign(s.entered.begin(), s.entered.end());
  e.retired.assign(s.retired.begin(), s.retired.end());
  for (const scantrace::EdgeCrossing& a : s.active_edges) {
    e.active_edges.push_back({a.edge, a.x});
    if (a.winding != 0) e.active_edges.back().winding = a.winding;
  }
  for (const scantrace::ActivePoint& p : s.active_points)
    e.active_points.push_back({p.x, p.edge, p.color});
  if (s.has_span) e.span = Span{s.span.x_begin, s.span.x_end};
  if (s.has_span && s.span.has_colors) e.span_colors = SpanColors{s.span.begin, s.span.end};
  if (s.has_intervals) {
    e.intervals.emplace();
    for (const scantrace::Span& i : s.intervals) {
      Interval x{i.left_edge, i.right_edge, i.x_left, i.x_right, Span{i.x_begin, i.x_end}, {}};
      if (i.has_colors) x.colors = SpanColors{i.begin, i.end};
      e.intervals->push_back(x);
    }
  }
  return e;
}

}  // namespace scantrace::trace
