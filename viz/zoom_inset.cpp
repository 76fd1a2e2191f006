#include "viz/zoom_inset.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

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

// How much of the triangle (and of the row's marks) an inset at `r` would hide.
double cost(const cv::Rect& r, const ViewGeometry& main, const std::vector<Vec2>& polygon,
            const std::vector<cv::Point2d>& marks) {
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
  for (const cv::Point2d& m : marks)
    if (r.contains(cv::Point(static_cast<int>(m.x), static_cast<int>(m.y)))) c += 1000;
  return c;
}

void draw_inset(cv::Mat& frame, const cv::Rect& r, double cell, const Typography& type,
                cv::Size canvas, const CanvasState& state, const trace::TriangleBegin* b,
                const trace::EdgeTableEvent* table, const trace::Scanline& row, double x,
                const std::string& title) {
  // A point far off the canvas is shown where the row enters the canvas.
  x = std::clamp(x, -2.0, canvas.width + 1.0);
  const std::int64_t cx = static_cast<std::int64_t>(std::floor(x + 0.5));
  const std::int64_t half_w = static_cast<std::int64_t>(r.width / cell / 2) + 1;
  const std::int64_t half_h = static_cast<std::int64_t>(r.height / cell / 2) + 1;
  const ViewGeometry g(r, {cx - half_w, row.y - half_h, cx + half_w, row.y + half_h}, cell);
  cv::rectangle(frame, r, palette::kHalo, type.px(6));
  GridView view(frame, g, type, canvas);
  view.cells(state);
  view.grid();
  if (b) view.outline(*b, palette::kOutline, 1);
  view.scanline(row.y, false);
  for (const trace::EdgeCrossing& a : row.active_edges)
    if (const trace::EdgeEntry* e = find_edge(table, a.edge))
      view.edge(e->from, e->to, e->edge, true);
  view.spans(row);
  view.active_points(row);
  type.draw_boxed(frame, title, {r.x + type.px(6), r.y + type.px(6)}, TextStyle::small,
                  palette::kText, palette::kLabelBox);
}

}  // namespace

void draw_zoom_insets(cv::Mat& frame, const ViewGeometry& main, const Typography& type,
                      cv::Size canvas, const CanvasState& state, const trace::TriangleBegin* b,
                      const trace::EdgeTableEvent* table, const trace::Scanline& row) {
  if (row.active_points.empty()) return;
  const cv::Rect& v = main.view();
  const int m = type.px(10);
  const cv::Size size(static_cast<int>(v.width * 0.42), static_cast<int>(v.height * 0.31));
  const std::array<cv::Rect, 4> corners{
      cv::Rect({v.x + m, v.y + m}, size), cv::Rect({v.x + v.width - m - size.width, v.y + m}, size),
      cv::Rect({v.x + m, v.y + v.height - m - size.height}, size),
      cv::Rect({v.x + v.width - m - size.width, v.y + v.height - m - size.height}, size)};
  const std::vector<Vec2> polygon = b ? polygon_of(*b) : std::vector<Vec2>{};
  std::vector<cv::Point2d> marks;
  for (const trace::ActivePoint& p : row.active_points)
    marks.push_back(main.to_frame(p.x, static_cast<double>(row.y)));
  std::array<double, 4> costs{};
  for (int i = 0; i < 4; ++i) costs[i] = cost(corners[i], main, polygon, marks);
  std::array<int, 4> order{0, 1, 2, 3};
  std::stable_sort(order.begin(), order.end(), [&](int a, int c) { return costs[a] < costs[c]; });

  const double left = row.active_points.front().x, right = row.active_points.back().x;
  const bool two = row.active_points.size() >= 2 && right - left > 4;
  // The left end goes to the more-left of the two corners, so leader lines do not cross.
  int l = order[0], r = order[1];
  if (two && corners[r].x < corners[l].x) std::swap(l, r);
  const double cell = type.px(kInsetCell);
  // A dashed grey line from the point to the nearest point of its inset: solid, it would read as
  // one more edge.
  auto leader = [&](const cv::Rect& inset, double x) {
    const cv::Point2d p = main.to_frame(x, static_cast<double>(row.y));
    const cv::Point2d q(std::clamp(p.x, double(inset.x), double(inset.x + inset.width)),
                        std::clamp(p.y, double(inset.y), double(inset.y + inset.height)));
    const double len = std::hypot(q.x - p.x, q.y - p.y), dash = type.px(6), gap = type.px(4);
    for (double s = 0; s < len; s += dash + gap) {
      const double e = std::min(len, s + dash);
      draw_segment(frame, p + (q - p) * (s / len), p + (q - p) * (e / len), v, palette::kMutedText,
                   type.px(1));
    }
  };
  leader(corners[l], left);
  if (two) leader(corners[r], right);
  draw_inset(frame, corners[l], cell, type, canvas, state, b, table, row, left,
             two ? "zoom: left end of the span" : "zoom: the active points");
  if (two)
    draw_inset(frame, corners[r], cell, type, canvas, state, b, table, row, right,
               "zoom: right end of the span");
}

}  // namespace scantrace::viz
