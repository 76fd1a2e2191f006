// Zoom insets show what a frame cannot, without hiding what it shows. On every step of a few
// replays whose cells are too small for a grid: no inset covers the span it explains, its title
// and labels lie inside it, two insets never show the same canvas pixel, and the insets hide few
// of the pixels filled so far (where
// the view has room elsewhere, which these triangles' views have: each leaves an empty corner
// on either side of its long edge).
//
// Everything compared is computed here from the trace: the span's box from its active points
// through the view's geometry, the filled pixels from the traced spans of the rows up to the
// step's, and the pixels an inset shows from its own active-point markers (read from the display
// list, named by their edge) and its width, at the documented 18 design pixels a canvas pixel.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "trace/record.hpp"
#include "viz/replayer.hpp"
#include "viz/trace_lookup.hpp"
#include "viz/typography.hpp"
#include "viz_test_support.hpp"

using namespace scantrace;

namespace {

trace::Trace rgb_triangle(std::array<Vec2, 3> v, int width, int height) {
  trace::TriangleInput t{v, {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}}, width, height};
  return test::record(t);
}

// The demo's and the explorer's default triangle; and a wide, flat one whose long edge goes the
// other way (its empty corners top left and bottom right).
std::vector<std::pair<std::string, trace::Trace>> traces() {
  return {{"course triangle", rgb_triangle({Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}}, 512, 512)},
          {"wide", rgb_triangle({Vec2{10, 300}, Vec2{400, 20}, Vec2{470, 120}}, 480, 320)}};
}

// The canvas columns `lo..hi` (inclusive) an inset shows, found from one of its markers.
struct Columns {
  std::int64_t lo = 0, hi = -1;
};

// Each inset of the main view (layer 0) with the layer its contents were drawn in (1, 2).
struct Inset {
  cv::Rect box;
  int layer = 0;
};

std::vector<Inset> insets_of(const viz::Frame& frame) {
  std::vector<Inset> out;
  int k = 0;
  for (const viz::Mark& m : frame.marks(viz::MarkKind::inset)) out.push_back({m.box, ++k});
  return out;
}

// From an active-point marker inside the inset: the marker's centre is the point (x, row) of the
// canvas, and the inset's cells are `cell` frame pixels wide. A pixel is shown when any part of
// its cell (x - 0.5 .. x + 0.5) is inside the box; a frame pixel's rounding is allowed for.
std::optional<Columns> columns_shown(const viz::Frame& frame, const Inset& inset,
                                     const trace::Scanline& row, double cell) {
  for (const viz::Mark& m : frame.marks(viz::MarkKind::active_point)) {
    if (m.layer != inset.layer) continue;
    for (const trace::ActivePoint& p : row.active_points) {
      if (m.what != fmt::format("e{}", p.edge)) continue;
      const double u = m.box.x + m.box.width / 2.0;
      const double a = p.x + (inset.box.x - u) / cell, b = p.x + (inset.box.br().x - u) / cell;
      constexpr double kRounding = 0.1;
      return Columns{static_cast<std::int64_t>(std::floor(a + 0.5 + kRounding)),
                     static_cast<std::int64_t>(std::ceil(b - 0.5 - kRounding))};
    }
  }
  return std::nullopt;
}

// The pixels filled up to row `last` of triangle 0, from the trace's spans.
std::set<std::pair<std::int64_t, std::int64_t>> filled(const trace::Trace& t, std::int64_t last) {
  std::set<std::pair<std::int64_t, std::int64_t>> out;
  for (const trace::Scanline* s : t.scanlines(0))
    if (s->y <= last && s->span)
      for (std::int64_t x = s->span->x_begin; x < s->span->x_end; ++x) out.insert({x, s->y});
  return out;
}

// The share of the inset's area over filled pixels, sampled at every fourth frame pixel.
double filled_share(const cv::Rect& r, const viz::ViewGeometry& g,
                    const std::set<std::pair<std::int64_t, std::int64_t>>& pixels) {
  int in = 0, all = 0;
  for (int v = r.y; v < r.y + r.height; v += 4)
    for (int u = r.x; u < r.x + r.width; u += 4) {
      ++all;
      in += pixels.count({g.pixel_x(u), g.pixel_y(v)}) ? 1 : 0;
    }
  return all ? double(in) / all : 0;
}

// The span's row between its outermost active points, as the main view draws it.
cv::Rect span_box(const viz::ViewGeometry& g, const trace::Scanline& row) {
  const double left = row.active_points.front().x, right = row.active_points.back().x;
  const cv::Point2d a = g.to_frame(left - 0.5, double(row.y) - 0.5);
  const cv::Point2d b = g.to_frame(right + 0.5, double(row.y) + 0.5);
  return cv::Rect(cv::Point(int(std::floor(a.x)), int(std::floor(a.y))),
                  cv::Point(int(std::ceil(b.x)) + 1, int(std::ceil(b.y)) + 1));
}

}  // namespace

TEST_CASE("zoom insets avoid their span and the filled pixels and show different places",
          "[viz][zoom]") {
  for (const auto& [name, trace] : traces())
    for (const cv::Size size : {cv::Size(640, 360), cv::Size(1280, 720), cv::Size(1920, 1080)}) {
      const viz::Typography type(size);
      const double cell = type.px(18);
      viz::Replayer r(trace, {}, size, "test");
      int with_insets = 0, pairs = 0;
      double worst = 0;
      for (std::size_t i = 0; i < r.steps().size(); ++i) {
        const viz::Step& step = r.steps()[i];
        if (step.kind != viz::StepKind::scanlines) continue;
        const trace::Scanline* row = viz::find_scanline(trace, step.triangle, step.last_row);
        if (!row || row->active_points.empty()) continue;
        INFO(name << " at " << size.width << "x" << size.height << ", step " << i + 1
                    << ", row " << row->y);
        const viz::Frame frame = r.display_list(i);
        const viz::ViewGeometry g = *r.geometry(i);
        const std::vector<Inset> insets = insets_of(frame);
        with_insets += insets.empty() ? 0 : 1;
        const auto pixels = filled(trace, step.last_row);
        std::vector<Columns> shown;
        for (const Inset& inset : insets) {
          INFO("inset " << inset.layer << " at " << inset.box);
          CHECK((inset.box & span_box(g, *row)).empty());
          // Its title and labels lie inside it: none is cut by its border.
          for (const viz::Mark& m : frame.marks(viz::MarkKind::label))
            if (m.layer == inset.layer) {
              const cv::Rect box(m.box.x, m.box.y, m.box.width, m.box.height);
              INFO("label " << m.what << " at " << box);
              CHECK((box & inset.box) == box);
            }
          worst = std::max(worst, filled_share(inset.box, g, pixels));
          if (const auto cols = columns_shown(frame, inset, *row, cell)) shown.push_back(*cols);
        }
        if (insets.size() == 2) {
          ++pairs;
          REQUIRE(shown.size() == 2);
          INFO("columns " << shown[0].lo << ".." << shown[0].hi << " and " << shown[1].lo << ".."
                          << shown[1].hi);
          CHECK((shown[0].hi < shown[1].lo || shown[1].hi < shown[0].lo));
        }
      }
      INFO(name << " at " << size.width << "x" << size.height);
      // Every scanline step of these triangles has room for its insets.
      CHECK(with_insets > 20);
      CHECK(pairs > 10);
      // At most a twentieth of any inset lies over filled pixels (the insets that covered the filled
      // triangle in its last steps lay over it with half or more of their area).
      CHECK(worst <= 0.05);
    }
}
