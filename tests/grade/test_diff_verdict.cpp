// diff's verdict (grade/diff_verdict.hpp): the first lines name the mistake in the catalogue's
// words, for each wrong renderer of wrong_renderers.hpp (its catalogue id is the test's own
// knowledge of what it did), for two mistakes at once, and for x accumulated in floating point
// (a scanline fill written here).
#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "grade/diff_report.hpp"
#include "grade/mistake_catalogue.hpp"
#include "src/painter.hpp"
#include "wrong_renderers.hpp"

using namespace gradetest;
using scantrace::grade::catalogue_mistake;
using scantrace::grade::diff;
using scantrace::grade::DiffReport;

namespace {

std::vector<std::string> ids(const DiffReport& r) {
  std::vector<std::string> out;
  for (const auto& v : r.verdict) out.push_back(v.id);
  return out;
}

bool names(const DiffReport& r, const std::string& id) {
  const auto v = ids(r);
  return std::find(v.begin(), v.end(), id) != v.end();
}

enum class SpanEnds { ceil, rounded, floor_ceil };

// A flat scanline fill as students write it: per edge, x starts at the edge's first row and is
// accumulated with x += dx/dy (`accumulate`), or computed from the edge's start on every row;
// spans ceil(x_L) .. ceil(x_R) - 1 (or round(x_L) .. round(x_R), or floor(x_L) .. ceil(x_R)),
// rows ceil(y_min) .. ceil(y_max) - 1, painter's order.
RgbImage scanline_render(const Scene& s, bool accumulate, SpanEnds ends = SpanEnds::ceil) {
  RgbImage img(s.width, s.height, Rgb32f::from(s.background));
  for (int f : order(s, false)) {
    const auto p = points(s, f);
    const Rgb32f colour = Rgb32f::from(reference::mean_color(colours(s, f)));
    struct Edge {
      double y0, y1, x, dxdy;
      Vec2 a;
    };
    std::vector<Edge> edges;
    for (int i = 0; i < 3; ++i) {
      Vec2 a = p[i], b = p[(i + 1) % 3];
      if (a.y == b.y) continue;
      if (a.y > b.y) std::swap(a, b);
      const double dxdy = (b.x - a.x) / (b.y - a.y);
      edges.push_back({std::ceil(a.y), std::ceil(b.y), a.x + (std::ceil(a.y) - a.y) * dxdy, dxdy, a});
    }
    const double ymin = std::min({p[0].y, p[1].y, p[2].y}), ymax = std::max({p[0].y, p[1].y, p[2].y});
    for (double y = std::ceil(ymin); y < std::ceil(ymax); ++y) {
      std::vector<double> xs;
      for (Edge& e : edges)
        if (y >= e.y0 && y < e.y1) {
          xs.push_back(accumulate ? e.x : e.a.x + (y - e.a.y) * e.dxdy);
          e.x += e.dxdy;
        }
      if (xs.size() != 2 || y < 0 || y >= s.height) continue;
      const auto [xl, xr] = std::minmax(xs[0], xs[1]);
      const double first = ends == SpanEnds::ceil      ? std::ceil(xl)
                           : ends == SpanEnds::rounded ? std::nearbyint(xl)
                                                       : std::floor(xl);
      const double end = ends == SpanEnds::ceil ? std::ceil(xr)  // exclusive
                         : ends == SpanEnds::rounded ? std::nearbyint(xr) + 1
                                                     : std::ceil(xr) + 1;
      for (double x = std::max(0.0, first); x < std::min<double>(s.width, end); ++x)
        img(static_cast<int>(x), static_cast<int>(y)) = colour;
    }
  }
  return img;
}

// Tall triangles with integer vertices whose edges have slopes like 0.1 or 0.7: their exact
// crossings are whole numbers every few rows, where a sum of dx/dy is a hair off.
Scene drift_scene() {
  Scene s;
  s.width = 220, s.height = 200;
  const double dxs[] = {10, 7, 3, 13, 9, 17, 11, 21};
  for (int k = 0; k < 8; ++k) {
    const double x = 6 + 26 * k, dx = dxs[k];
    const int base = static_cast<int>(s.vertices.size());
    s.vertices.push_back({x, 5});
    s.vertices.push_back({x + 20 + dx, 105});
    s.vertices.push_back({x + dx / 2, 195});
    for (int i = 0; i < 3; ++i) {
      s.vcolors.push_back({0.1 * k, 0.5, 1 - 0.1 * k});
      s.depth.push_back(10.0 + k);
    }
    s.faces.push_back({base, base + 1, base + 2});
  }
  return s;
}

}  // namespace

TEST_CASE("verdict: each usual mistake is named first, in the catalogue's words",
          "[grade][diff][verdict]") {
  const Scene s = generated_scene();
  const std::pair<Mistake, Shading> cases[] = {
      {Mistake::closed_rule, Shading::flat},
      {Mistake::bottom_row_dropped, Shading::flat},
      {Mistake::span_too_wide, Shading::flat},
      {Mistake::order_reversed, Shading::gouraud},
      {Mistake::horizontal_edge_skipped, Shading::flat},
      {Mistake::degenerate_drawn, Shading::flat},
      {Mistake::flat_colour_not_mean, Shading::flat},
      {Mistake::gouraud_weights_permuted, Shading::gouraud}};
  for (const auto& [m, sh] : cases) {
    const std::string id = catalogue_id(m);
    const DiffReport r = diff(s, opts(sh), as_8bit(render_wrong(s, sh, m)));
    INFO(id << ": " << r.to_json()["verdict"].dump() << " " << r.to_json()["categories"].dump());
    REQUIRE_FALSE(r.verdict.empty());
    CHECK(r.verdict.front().id == id);
    CHECK(r.verdict.front().text == catalogue_mistake(id).verdict);
    // Printed before the categories, and in report.json.
    const std::string md = r.to_markdown();
    CHECK(md.find(catalogue_mistake(id).verdict) < md.find("pixels differ"));
    CHECK(r.to_json()["verdict"][0]["id"] == id);
  }
}

TEST_CASE("verdict: two mistakes at once are both named", "[grade][diff][verdict]") {
  const Scene s = generated_scene();
  const RgbImage img =
      render_wrong(s, Shading::flat, {Mistake::span_too_wide, Mistake::bottom_row_dropped});
  const DiffReport r = diff(s, opts(Shading::flat), as_8bit(img));
  INFO(r.to_json()["verdict"].dump() << " " << r.to_json()["categories"].dump());
  CHECK(names(r, "span_too_wide"));
  CHECK(names(r, "bottom_row_dropped"));
}

TEST_CASE("verdict: a face moved by one pixel is named, with what the image cannot tell",
          "[grade][diff][verdict]") {
  const Scene s = generated_scene();
  const DiffReport r =
      diff(s, opts(Shading::flat), as_8bit(render_wrong(s, Shading::flat, Mistake::shift_right)));
  INFO(r.to_json()["verdict"].dump() << " " << r.to_json()["categories"].dump());
  CHECK_FALSE(names(r, "span_too_wide"));
  CHECK(names(r, "edge_lag"));
  const bool says_grade = std::any_of(r.verdict.begin(), r.verdict.end(), [](const auto& v) {
    return v.id.empty() && v.evidence.find("scantrace grade") != std::string::npos;
  });
  CHECK(says_grade);
}

TEST_CASE("verdict: x accumulated in floating point drifts, and is not the closed rule",
          "[grade][diff][verdict]") {
  const Scene s = drift_scene();
  // The test's fill computing x from the edge's start is the reference's, pixel for pixel.
  const RgbImage exact = scanline_render(s, false);
  REQUIRE(count_differing(exact, render<Rgb32f>(s, opts(Shading::flat))) == 0);
  const RgbImage drift = scanline_render(s, true);
  const long long n = count_differing(exact, drift);
  REQUIRE(n >= 10);
  const DiffReport r = diff(s, opts(Shading::flat), as_8bit(drift));
  INFO(r.to_json()["verdict"].dump() << " " << r.to_json()["categories"].dump());
  CHECK(r.differing_pixels == n);
  CHECK(names(r, "float_drift"));
  CHECK_FALSE(names(r, "closed_rule"));
  CHECK(r.verdict.front().text == "x drifts: accumulated with x += dx/dy in floating point");
}

TEST_CASE("verdict: span ends rounded to the nearest pixel are told from spans too wide",
          "[grade][diff][verdict]") {
  const Scene s = drift_scene();
  for (const auto& [ends, id] : {std::pair{SpanEnds::rounded, "span_end_rounding"},
                                 std::pair{SpanEnds::floor_ceil, "span_too_wide"}}) {
    const DiffReport r = diff(s, opts(Shading::flat), as_8bit(scanline_render(s, false, ends)));
    INFO(id << ": " << r.to_json()["verdict"].dump() << " " << r.to_json()["categories"].dump());
    REQUIRE_FALSE(r.verdict.empty());
    CHECK(r.verdict.front().id == id);
  }
}
