#include "viz/zoom_inset.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "viz/grid_view.hpp"
#include "viz/palette.hpp"
#include "viz/trace_lookup.hpp"

namespace scantrace::viz {
namespace {

constexpr double kInsetCell = 18;  // design pixels per canvas pixel inside an inset

bool inside_polygon(const std::vector<Vec2>& p, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
    if ((p[i].y > y) != (p[j].y > y) &&
        x < (p[j].x - p[i].x) * (y - p[i].y) / (p[j].y - p[i].y) + p[i].x)
      in = !in;
  return in;
}

// How much of the polygon an inset at `r` would hide (markers and labels it may not hide at all).
double cost(const Rect& r, const ViewGeometry& main, const std::vector<Vec2>& polygon) {
  double c = 0;
  constexpr int kSamples = 12;
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kSamples; ++j) {
      const int u = r.x + (2 * i + 1) * r.width / (2 * kSamples);
      const int v = r.y + (2 * j + 1) * r.height / (2 * kSamples);
      if (!polygon.empty() && inside_polygon(polygon, static_cast<double>(main.pixel_x(u)),
                                             static_cast<double>(main.pixel_y(v))))
        c += 1;
    }
  return c;
}

// The point of `r` nearest `p`: where a leader line from `p` meets the inset.
Point2d nearest(const Rect& r, Point2d p) {
  return {std::clamp(p.x, double(r.x), double(r.x + r.width)),
          std::clamp(p.y, double(r.y), double(r.y + r.height))};
}

// Whether segments a-b and c-d cross (touching ends do not count).
bool crosses(Point2d a, Point2d b, Point2d c, Point2d d) {
  const auto side = [](Point2d p, Point2d q, Point2d r) { return (q - p).cross(r - p); };
  const double d1 = side(c, d, a), d2 = side(c, d, b), d3 = side(a, b, c), d4 = side(a, b, d);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

std::vector<PlacedBox> draw_inset(FrameView& frame, const Rect& r, int layer, double cell,
                                  const Typography& type, Size canvas, const CanvasState& state,
                                  const trace::TriangleBegin* b, const trace::EdgeTableEvent* table,
                                  const trace::Scanline& row, double x, const std::string& title) {
  // A point far off the canvas is shown where the row enters the canvas.
  x = std::clamp(x, -2.0, canvas.width + 1.0);
  const std::int64_t cx = static_cast<std::int64_t>(std::floor(x + 0.5));
  const std::int64_t half_w = static_cast<std::int64_t>(r.width / cell / 2) + 1;
  const std::int64_t half_h = static_cast<std::int64_t>(r.height / cell / 2) + 1;
  const ViewGeometry g(r, {cx - half_w, row.y - half_h, cx + half_w, row.y + half_h}, cell);
  // The inset is a box of the main view (layer 0), as the placement counts it.
  frame.rectangle(r, palette::kHalo, type.px(6), LINE_8,
                  Mark{MarkKind::inset, title, r + frame.area().tl(), 0});
  GridView view(frame, g, type, canvas, layer);
  view.cells(state);
  view.grid();
  if (b) view.outline(*b, palette::kOutline, 1);
  view.scanline(row.y);
  for (const trace::EdgeCrossing& a : row.active_edges)
    if (const trace::EdgeEntry* e = find_edge(table, a.edge))
      view.edge(e->from, e->to, e->edge, true);
  view.spans(row);
  // The title is in the inset's top-left corner whatever else is there; the x labels go round it.
  const Point title_at{r.x + type.px(6), r.y + type.px(6)};
  view.placement().mark(PlacedKind::label, type.boxed_area(title, title_at, TextStyle::small),
                        title);
  view.active_points(row);
  type.draw_boxed(
      frame, title, title_at, TextStyle::small, palette::kText, palette::kLabelBox, std::nullopt,
      Mark{MarkKind::label, title,
           type.boxed_area(title, title_at, TextStyle::small) + frame.area().tl(), layer});
  return view.placement().boxes();
}

}  // namespace

std::vector<PlacedBox> draw_zoom_insets(FrameView& frame, const ViewGeometry& main,
                                        const Typography& type, Size canvas,
                                        const CanvasState& state, const trace::TriangleBegin* b,
                                        const trace::EdgeTableEvent* table,
                                        const trace::Scanline& row, Placement& placed) {
  if (row.active_points.empty()) return {};
  const Rect& v = main.view();
  const int m = type.px(10);
  const std::vector<Vec2> polygon = b ? polygon_of(*b) : std::vector<Vec2>{};
  const double left = row.active_points.front().x, right = row.active_points.back().x;
  const bool two = row.active_points.size() >= 2 && right - left > 4;

  const Point2d at_left = main.to_frame(left, static_cast<double>(row.y));
  const Point2d at_right = main.to_frame(right, static_cast<double>(row.y));

  // Largest first; at each size the free places (corners and the middles of the sides) that hide
  // least of the polygon. A pair must not overlap, and its leader lines should neither cross nor
  // send the left end to the inset on the right: a student follows each line by eye.
  std::optional<Rect> first, second;
  for (const double shrink : {1.0, 0.8, 0.64, 0.5}) {
    const Size size(static_cast<int>(v.width * 0.42 * shrink),
                    static_cast<int>(v.height * 0.31 * shrink));
    const int x0 = v.x + m, x1 = v.x + v.width - m - size.width, xm = (x0 + x1) / 2;
    const int y0 = v.y + m, y1 = v.y + v.height - m - size.height, ym = (y0 + y1) / 2;
    std::vector<std::pair<double, Rect>> free;
    for (const Point p :
         {Point{x0, y0}, {x1, y0}, {x0, y1}, {x1, y1}, {xm, y0}, {xm, y1}, {x0, ym}, {x1, ym}})
      if (const Rect r(p, size); placed.free(r)) free.emplace_back(cost(r, main, polygon), r);
    double best = INFINITY;
    for (std::size_t i = 0; i < free.size(); ++i) {
      if (!two) {
        if (free[i].first < best) best = free[i].first, first = free[i].second;
        continue;
      }
      for (std::size_t j = 0; j < free.size(); ++j) {
        const Rect &a = free[i].second, &c = free[j].second;
        if (i == j || !(a & c).empty()) continue;
        double total = free[i].first + free[j].first;
        if (crosses(at_left, nearest(a, at_left), at_right, nearest(c, at_right))) total += 1000;
        if (c.x + c.width / 2 < a.x + a.width / 2) total += 100;
        if (total < best) best = total, first = a, second = c;
      }
    }
    if (first) break;
  }
  if (!first) return {};

  const double cell = type.px(kInsetCell);
  // A dashed grey line from the point to the nearest point of its inset: solid, it would read as
  // one more edge. Dashes that would cross a marker or a label are left out.
  auto leader = [&](const Rect& inset, double x) {
    const Point2d p = main.to_frame(x, static_cast<double>(row.y));
    const Point2d q = nearest(inset, p);
    const double len = std::hypot(q.x - p.x, q.y - p.y), dash = type.px(6), gap = type.px(4);
    for (double s = 0; s < len; s += dash + gap) {
      const double e = std::min(len, s + dash);
      const Point2d a = p + (q - p) * (s / len), c = p + (q - p) * (e / len);
      const int pad = type.px(1);
      const Rect around_dash(Point(int(std::floor(std::min(a.x, c.x))) - pad,
                                   int(std::floor(std::min(a.y, c.y))) - pad),
                             Point(int(std::ceil(std::max(a.x, c.x))) + pad + 1,
                                   int(std::ceil(std::max(a.y, c.y))) + pad + 1));
      if (!placed.free(around_dash & v)) continue;
      draw_segment(frame, a, c, v, palette::kMutedText, type.px(1));
    }
  };
  leader(*first, left);
  if (two) leader(*second, right);
  const std::string title_one = two ? "zoom: left end of the span" : "zoom: the active points";
  placed.mark(PlacedKind::inset, *first, title_one);
  std::vector<PlacedBox> inside =
      draw_inset(frame, *first, 1, cell, type, canvas, state, b, table, row, left, title_one);
  if (two) {
    placed.mark(PlacedKind::inset, *second, "zoom: right end of the span");
    std::vector<PlacedBox> more = draw_inset(frame, *second, 2, cell, type, canvas, state, b, table,
                                             row, right, "zoom: right end of the span");
    inside.insert(inside.end(), more.begin(), more.end());
  }
  return inside;
}

}  // namespace scantrace::viz
