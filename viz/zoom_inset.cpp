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

// What an inset would hide, sampled once a frame on a 48 x 48 grid over the view: the pixels
// filled so far weigh most (they are what the frames so far have explained), the rest of the
// polygon less (its pixels are still to come). Markers and labels it may not hide at all; the
// placement keeps them free. Sums over the grid's cells (a summed-area table) make each of the
// few hundred places a frame weighs four look-ups.
class HiddenCost {
 public:
  HiddenCost(const ViewGeometry& main, const CanvasState& state, const std::vector<Vec2>& polygon)
      : view_(main.view()), sum_((kCells + 1) * (kCells + 1), 0) {
    for (int j = 0; j < kCells; ++j)
      for (int i = 0; i < kCells; ++i) {
        const std::int64_t x = main.pixel_x(centre(view_.x, view_.width, i));
        const std::int64_t y = main.pixel_y(centre(view_.y, view_.height, j));
        double w = 0;
        if (state.written(x, y))
          w = 3;
        else if (!polygon.empty() &&
                 inside_polygon(polygon, static_cast<double>(x), static_cast<double>(y)))
          w = 1;
        at(i + 1, j + 1) = w + at(i, j + 1) + at(i + 1, j) - at(i, j);
      }
  }

  // The mean weight of the grid cells whose centres lie in `r`, as 144 samples of it would sum.
  double operator()(const Rect& r) const {
    const int i0 = first(view_.x, view_.width, r.x), i1 = first(view_.x, view_.width, r.x + r.width);
    const int j0 = first(view_.y, view_.height, r.y);
    const int j1 = first(view_.y, view_.height, r.y + r.height);
    const int n = (i1 - i0) * (j1 - j0);
    if (n <= 0) return 0;
    return 144 * (at(i1, j1) - at(i0, j1) - at(i1, j0) + at(i0, j0)) / n;
  }

 private:
  static constexpr int kCells = 48;
  static int centre(int from, int length, int i) { return from + (2 * i + 1) * length / (2 * kCells); }
  // The first cell whose centre is at or right of (below) frame coordinate `u`.
  static int first(int from, int length, int u) {
    int i = 0;
    while (i < kCells && centre(from, length, i) < u) ++i;
    return i;
  }
  double& at(int i, int j) { return sum_[j * (kCells + 1) + i]; }
  double at(int i, int j) const { return sum_[j * (kCells + 1) + i]; }

  Rect view_;
  std::vector<double> sum_;
};

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

// The canvas pixels an inset of `size` shows around canvas x `centre` (a whole pixel or the border
// between two), on `row`: exactly kInsetCell design pixels a canvas pixel, so that the pixels an
// inset shows follow from its width alone.
ViewGeometry inset_geometry(const Rect& r, double cell, double centre, std::int64_t row) {
  // A region of odd width is centred on a pixel, of even width on the border between two.
  const auto span = [&](int frame_pixels, bool even) {
    std::int64_t n = std::max<std::int64_t>(1, static_cast<std::int64_t>(frame_pixels / cell));
    if ((n % 2 == 0) != even && n > 1) --n;
    return n;
  };
  const bool on_border = std::abs(centre - std::round(centre)) > 0.25;
  const std::int64_t w = span(r.width, on_border), h = span(r.height, false);
  const std::int64_t x0 = static_cast<std::int64_t>(std::floor(centre - (w - 1) / 2.0 + 0.25));
  return ViewGeometry(r, {x0, row - (h - 1) / 2, x0 + w - 1, row + (h - 1) / 2}, cell);
}

std::vector<PlacedBox> draw_inset(FrameView& frame, const Rect& r, int layer, double cell,
                                  const Typography& type, Size canvas, const CanvasState& state,
                                  const trace::TriangleBegin* b, const trace::EdgeTableEvent* table,
                                  const trace::Scanline& row, double centre,
                                  const std::string& title) {
  const ViewGeometry g = inset_geometry(r, cell, centre, row.y);
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

// What the insets show: one inset centred on the span when the whole span fits in it with a
// pixel to spare each side, else one for each end. Two insets never share a pixel: when the ends
// are closer than an inset's width, the two windows meet at the border between two pixels in the
// span's middle.
struct InsetPlan {
  bool two = false;
  double centre[2] = {0, 0};  // canvas x each inset is centred on
  double from[2] = {0, 0};    // canvas x its leader line starts at
};

InsetPlan plan_for(double left, double right, bool several, double half) {
  InsetPlan p;
  if (!several || right - left <= 2 * half - 3) {
    p.centre[0] = p.from[0] = (left + right) / 2;
    return p;
  }
  p.two = true;
  p.from[0] = left;
  p.from[1] = right;
  // A frame pixel's rounding either side of the border is kept clear of the other window.
  const double border = std::floor((left + right) / 2) + 0.5, clear = half + 0.1;
  p.centre[0] = std::min(std::floor(left + 0.5), border - clear);
  p.centre[1] = std::max(std::floor(right + 0.5), border + clear);
  // A window centred off a pixel centre or border is moved onto the nearest one inside.
  p.centre[0] = std::floor(p.centre[0] * 2) / 2;
  p.centre[1] = std::ceil(p.centre[1] * 2) / 2;
  return p;
}

struct Candidate {
  Rect r;
  double cost = 0;
};

// The places an inset of `size` may take in the view `v`: a 9 x 9 grid of positions (corners and
// the middles of the sides among them) that cover no marker and no label, nor the span itself.
// The rest of the scanline is better left in sight too: it costs as much as a sixth of the inset
// over filled pixels.
std::vector<Candidate> candidates(const Rect& v, int margin, Size size, const Rect& span,
                                  const HiddenCost& cost, const Placement& placed) {
  std::vector<Candidate> out;
  const int x0 = v.x + margin, x1 = v.x + v.width - margin - size.width;
  const int y0 = v.y + margin, y1 = v.y + v.height - margin - size.height;
  if (x1 < x0 || y1 < y0) return out;
  constexpr int kSteps = 8;
  for (int i = 0; i <= kSteps; ++i)
    for (int j = 0; j <= kSteps; ++j) {
      const Rect r(Point{x0 + (x1 - x0) * i / kSteps, y0 + (y1 - y0) * j / kSteps}, size);
      if (!placed.free(r) || !(r & span).empty()) continue;
      const bool on_row = r.y < span.y + span.height && span.y < r.y + r.height;
      out.push_back({r, cost(r) + (on_row ? 72 : 0)});
    }
  std::stable_sort(out.begin(), out.end(),
                   [](const Candidate& a, const Candidate& b) { return a.cost < b.cost; });
  return out;
}

// The frame box of the span's row between its ends, with the room a student's eye needs round it.
Rect span_box(const ViewGeometry& main, double left, double right, std::int64_t y, int pad) {
  const Point2d a = main.to_frame(left - 0.5, static_cast<double>(y) - 0.5);
  const Point2d c = main.to_frame(right + 0.5, static_cast<double>(y) + 0.5);
  return Rect(Point(int(std::floor(a.x)) - pad, int(std::floor(a.y)) - pad),
              Point(int(std::ceil(c.x)) + pad + 1, int(std::ceil(c.y)) + pad + 1));
}

struct Choice {
  double total = INFINITY;
  Rect r[2];
  InsetPlan plan;
};

// The best place (or pair of places) among `c`: least hidden, leader lines short, not crossing,
// and the left end's inset left of the right end's, which a student follows by eye. `c` is sorted
// by cost: a pair is not weighed once its costs alone reach the best total so far.
void choose(const std::vector<Candidate>& c, const InsetPlan& plan, const ViewGeometry& main,
            std::int64_t y, double penalty, Choice& best) {
  const Rect& v = main.view();
  const Point2d at[2] = {main.to_frame(plan.from[0], double(y)),
                         main.to_frame(plan.from[1], double(y))};
  const auto reach = [&](const Rect& r, int k) {
    const Point2d q = nearest(r, at[k]);
    return 8 * std::hypot(q.x - at[k].x, q.y - at[k].y) / (v.width + v.height);
  };
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (penalty + c[i].cost + (plan.two ? c.front().cost : 0) >= best.total) break;
    const double one = penalty + c[i].cost + reach(c[i].r, 0);
    if (!plan.two) {
      if (one < best.total) best = {one, {c[i].r, {}}, plan};
      continue;
    }
    for (std::size_t j = 0; j < c.size() && one + c[j].cost < best.total; ++j) {
      const Rect &a = c[i].r, &d = c[j].r;
      if (i == j || !(a & d).empty()) continue;
      double total = one + c[j].cost + reach(d, 1);
      if (crosses(at[0], nearest(a, at[0]), at[1], nearest(d, at[1]))) total += 1000;
      if (d.x + d.width / 2 < a.x + a.width / 2) total += 100;
      if (total < best.total) best = {total, {a, d}, plan};
    }
  }
}

// A dashed grey line from the point to the nearest point of its inset: solid, it would read as
// one more edge. Dashes that would cross a marker or a label are left out.
void leader(FrameView& frame, const ViewGeometry& main, const Typography& type,
            const Placement& placed, const Rect& inset, double x, std::int64_t y) {
  const Rect& v = main.view();
  const Point2d p = main.to_frame(x, static_cast<double>(y));
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
}

// Inset k's title, in full where the inset is wide enough for it, else shortened; empty when
// not even that fits (the size is then not taken).
std::string title_of(const InsetPlan& plan, int k, int width, const Typography& type) {
  const char* full[2] = {plan.two ? "zoom: left end of the span" : "zoom: the span",
                         "zoom: right end of the span"};
  const char* brief[2] = {plan.two ? "zoom: left end" : "zoom: span", "zoom: right end"};
  for (const char* title : {full[k], brief[k]})
    if (type.boxed_area(title, {0, 0}, TextStyle::small).width + 2 * type.px(6) <= width)
      return title;
  return {};
}

}  // namespace

std::vector<PlacedBox> draw_zoom_insets(FrameView& frame, const ViewGeometry& main,
                                        const Typography& type, Size canvas,
                                        const CanvasState& state, const trace::TriangleBegin* b,
                                        const trace::EdgeTableEvent* table,
                                        const trace::Scanline& row, Placement& placed) {
  if (row.active_points.empty()) return {};
  const Rect& v = main.view();
  const std::vector<Vec2> polygon = b ? polygon_of(*b) : std::vector<Vec2>{};
  // A point far off the canvas is shown where the row enters the canvas.
  const auto on_canvas = [&](double x) { return std::clamp(x, -2.0, canvas.width + 1.0); };
  const double left = on_canvas(row.active_points.front().x);
  const double right = on_canvas(row.active_points.back().x);
  const double cell = type.px(kInsetCell);
  const Rect span = span_box(main, left, right, row.y, type.px(4));
  const HiddenCost cost(main, state, polygon);

  // Every size, largest first: a smaller inset over empty canvas is worth more than a large one
  // over the pixels the frames have filled (a sample of filled pixel costs 3, the penalties of
  // the smaller sizes are a few samples).
  Choice best;
  const double shrinks[] = {1.0, 0.8, 0.64, 0.5}, penalties[] = {0, 4, 8, 14};
  for (int k = 0; k < 4; ++k) {
    const Size size(static_cast<int>(v.width * 0.42 * shrinks[k]),
                    static_cast<int>(v.height * 0.31 * shrinks[k]));
    const InsetPlan plan =
        plan_for(left, right, row.active_points.size() >= 2, size.width / (2 * cell));
    if (title_of(plan, plan.two ? 1 : 0, size.width, type).empty()) continue;
    choose(candidates(v, type.px(10), size, span, cost, placed), plan, main, row.y, penalties[k],
           best);
  }
  if (!std::isfinite(best.total)) return {};

  const InsetPlan& plan = best.plan;
  leader(frame, main, type, placed, best.r[0], plan.from[0], row.y);
  if (plan.two) leader(frame, main, type, placed, best.r[1], plan.from[1], row.y);
  const std::string titles[2] = {title_of(plan, 0, best.r[0].width, type),
                                 title_of(plan, 1, best.r[0].width, type)};
  std::vector<PlacedBox> inside;
  for (int k = 0; k < (plan.two ? 2 : 1); ++k) {
    placed.mark(PlacedKind::inset, best.r[k], titles[k]);
    std::vector<PlacedBox> more = draw_inset(frame, best.r[k], k + 1, cell, type, canvas, state, b,
                                             table, row, plan.centre[k], titles[k]);
    inside.insert(inside.end(), more.begin(), more.end());
  }
  return inside;
}

}  // namespace scantrace::viz
