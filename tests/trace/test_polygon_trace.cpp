// Convex polygons narrate themselves through the same fill: all their edges in the edge table,
// two active edges per row, spans equal to the pixels written.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "src/scanline_fill.hpp"
#include "src/winding_fill.hpp"
#include "trace/event_tracer.hpp"
#include "trace/record.hpp"
#include "trace/recorder.hpp"

using namespace scantrace;
using namespace scantrace::trace;

TEST_CASE("a convex polygon's trace lists every edge and two active edges per row", "[trace]") {
  // A regular heptagon around (40.3, 33.7), radius 25, rotated so no edge is horizontal.
  std::vector<Vec2> points;
  std::vector<Color> colors;
  for (int k = 0; k < 7; ++k) {
    const double a = 0.3 + 2 * std::numbers::pi * k / 7;
    points.push_back({40.3 + 25 * std::cos(a), 33.7 + 25 * std::sin(a)});
    colors.push_back({k / 6.0, 1 - k / 6.0, 0.5});
  }
  const FillOptions options{.shading = Shading::gouraud};
  RgbImage image(80, 70, Rgb32f{-1, -1, -1});
  EventTracer<Recorder> tracer(Recorder(make_header(80, 70, options, TraceLevel::scanline)), {});
  fill_convex_polygon(image, points, colors, options, tracer);
  const Trace t = tracer.finish();

  const EdgeTableEvent& table = t.edge_table(0);
  CHECK(table.edges.size() == 7);
  CHECK(table.horizontal.empty());
  for (std::size_t i = 1; i < table.edges.size(); ++i)
    CHECK(table.edges[i - 1].first_row <= table.edges[i].first_row);

  const auto rows = t.scanlines(0);
  double y_min = points[0].y, y_max = points[0].y;
  for (const Vec2& p : points) y_min = std::min(y_min, p.y), y_max = std::max(y_max, p.y);
  CHECK(rows.front()->y == static_cast<i64>(std::ceil(y_min)));  // no vertex is near a row centre
  CHECK(rows.back()->y == static_cast<i64>(std::ceil(y_max)) - 1);
  for (const Scanline* s : rows) {
    CAPTURE(s->y);
    REQUIRE(s->active_edges.size() == 2);
    // The active points' colours are the vertex colours interpolated along each edge.
    for (const trace::ActivePoint& p : s->active_points) {
      const Vec2 a = points[p.edge], b = points[(p.edge + 1) % 7];
      const double w = (static_cast<double>(s->y) - a.y) / (b.y - a.y);
      const Color want = colors[p.edge] * (1 - w) + colors[(p.edge + 1) % 7] * w;
      CHECK(p.color.r == Approx(want.r).margin(1e-3));  // vertices snapped to 1/256 px
      CHECK(p.color.g == Approx(want.g).margin(1e-3));
      CHECK(p.x == Approx(a.x + (b.x - a.x) * w).margin(1e-2));
    }
    for (int x = 0; x < 80; ++x)
      CHECK((s->span && s->span->contains(x)) ==
            !(image(x, static_cast<int>(s->y)) == Rgb32f{-1, -1, -1}));
  }
}

namespace {

// A square (2,2)-(20,20) with a square hole (8,8)-(14,14) running the other way round, so it is a
// hole under both rules. Edges 0 and 2 (outer) and 5 and 7 (hole) are horizontal.
GeneralPolygonInput square_with_hole() {
  GeneralPolygonInput p;
  p.contours = {{{2, 2}, {20, 2}, {20, 20}, {2, 20}}, {{8, 8}, {8, 14}, {14, 14}, {14, 8}}};
  p.colors = {{1, 0, 0}, {0, 1, 0}, {0, 1, 0}, {0, 0, 1},
              {1, 1, 0}, {0, 1, 1}, {0, 1, 1}, {1, 1, 0}};
  p.width = 24;
  p.height = 24;
  return p;
}

void check_row_10(const Trace& t) {
  // Hand-computed: on row 10 four edges are active, left to right e3 (x = 2, going up), e4
  // (x = 8, down), e6 (x = 14, up), e1 (x = 20, down). Winding after each: -1, 0, -1, 0, so the
  // inside intervals are e3..e4 (pixels 2..7) and e6..e1 (pixels 14..19).
  const Scanline& s = t.scanline(0, 10);
  REQUIRE(s.active_edges.size() == 4);
  const int ids[] = {3, 4, 6, 1}, windings[] = {-1, 1, -1, 1};
  const double xs[] = {2, 8, 14, 20};
  for (int i = 0; i < 4; ++i) {
    CHECK(s.active_edges[i].edge == ids[i]);
    CHECK(s.active_edges[i].x == xs[i]);
    REQUIRE(s.active_edges[i].winding);
    CHECK(*s.active_edges[i].winding == windings[i]);
  }
  REQUIRE(s.intervals);
  REQUIRE(s.intervals->size() == 2);
  const Interval &a = (*s.intervals)[0], &b = (*s.intervals)[1];
  CHECK(a.left_edge == 3);
  CHECK(a.right_edge == 4);
  CHECK(a.pixels.x_begin == 2);
  CHECK(a.pixels.x_end == 8);
  CHECK(b.left_edge == 6);
  CHECK(b.right_edge == 1);
  CHECK(b.pixels.x_begin == 14);
  CHECK(b.pixels.x_end == 20);
  // e3 runs from v3 (2, 20) blue up to v0 (2, 2) red: at y = 10, 8/18 of the way from red.
  REQUIRE(a.colors);
  CHECK(a.colors->begin.r == Approx(10.0 / 18));
  CHECK(a.colors->begin.b == Approx(8.0 / 18));
  // `span` is the first interval.
  REQUIRE(s.span);
  CHECK(s.span->x_begin == 2);
  CHECK(s.span->x_end == 8);
  // The pixel in the second interval is found by the reader, in the hole nobody wrote.
  CHECK_FALSE(t.pixel_history(16, 10).empty());
  CHECK(t.pixel_history(10, 10).empty());
}

}  // namespace

TEST_CASE("a polygon with a hole: the trace shows all active edges, windings and intervals",
          "[trace][polygon]") {
  for (const char* rule : {"even-odd", "non-zero"}) {
    FillOptions options;
    REQUIRE(parse_winding_rule(rule, options.winding_rule));
    RgbImage image;
    const Trace t = record_polygon(square_with_hole(), options, {}, &image);
    CHECK(t.header().winding_rule == options.winding_rule);
    const TriangleBegin& b = t.triangle_begin(0);
    CHECK(b.vertices.size() == 8);
    CHECK(b.contours == std::vector<std::vector<int>>{{0, 1, 2, 3}, {4, 5, 6, 7}});
    // The edge table's `to` is the next vertex of the contour: e3 ends at v0, e6 at v7.
    for (const EdgeEntry& e : t.edge_table(0).edges) {
      if (e.edge == 3) CHECK((e.to.x == 2 && e.to.y == 2));
      if (e.edge == 6) CHECK((e.to.x == 14 && e.to.y == 8));
    }
    CHECK(t.edge_table(0).horizontal.size() == 4);
    check_row_10(t);
    // Every row's intervals are exactly the pixels written on it.
    for (const Scanline* s : t.scanlines(0))
      for (int x = 0; x < 24; ++x) {
        bool in = false;
        for (const Interval& iv : *s->intervals) in = in || iv.pixels.contains(x);
        CHECK(in == !(image(x, static_cast<int>(s->y)) == Rgb32f::from(Color{1, 1, 1})));
      }
    CHECK(t.triangle_end(0)->pixels == 18 * 18 - 6 * 6);
  }
}

TEST_CASE("a polygon trace survives the file: intervals and windings are read back",
          "[trace][polygon]") {
  const auto path = std::filesystem::temp_directory_path() / "scantrace_polygon_trace_test.jsonl";
  FillOptions options;
  options.winding_rule = WindingRule::non_zero;
  write_polygon_trace(path, square_with_hole(), options);
  const Trace t = Trace::load(path);
  std::filesystem::remove(path);
  CHECK(t.header().winding_rule == WindingRule::non_zero);
  check_row_10(t);
}

TEST_CASE("a pentagram row crosses four edges and non-zero merges the centre into one interval",
          "[trace][polygon]") {
  GeneralPolygonInput p;
  p.contours = {{{10, 1}, {15.5, 18.2}, {1.3, 7.3}, {18.7, 7.3}, {4.5, 18.2}}};
  p.colors.assign(5, Color{0.2, 0.4, 0.6});
  p.width = p.height = 20;
  FillOptions eo, nz;
  nz.winding_rule = WindingRule::non_zero;
  const Trace a = record_polygon(p, eo), b = record_polygon(p, nz);
  // Row 12 passes below the star's arms through its centre: four edges, the middle two bound the
  // central pentagon (winding 2), which even-odd leaves out and non-zero fills.
  REQUIRE(a.scanline(0, 12).active_edges.size() == 4);
  CHECK(a.scanline(0, 12).intervals->size() == 2);
  CHECK(b.scanline(0, 12).intervals->size() == 1);
  const Interval& whole = b.scanline(0, 12).intervals->front();
  CHECK(whole.left_edge == a.scanline(0, 12).active_edges.front().edge);
  CHECK(whole.right_edge == a.scanline(0, 12).active_edges.back().edge);
}

TEST_CASE("tracing a polygon does not change what it fills", "[trace][polygon]") {
  GeneralPolygonInput p = square_with_hole();
  p.contours.push_back({{4.5, 12.3}, {17.5, 5.2}, {16, 17}});  // a third contour, crossing both
  p.colors.insert(p.colors.end(), {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  for (WindingRule rule : {WindingRule::even_odd, WindingRule::non_zero})
    for (Shading shading : {Shading::gouraud, Shading::flat}) {
      FillOptions options;
      options.winding_rule = rule;
      options.shading = shading;
      RgbImage traced;
      const Trace t = record_polygon(p, options, {.level = TraceLevel::pixel}, &traced);
      RgbImage plain(p.width, p.height, Rgb32f::from(p.background));
      const FillResult r =
          fill_polygon_contours(plain, std::span(p.contours), std::span(p.colors), options);
      CHECK(t.triangle_end(0)->pixels == r.pixels);
      CHECK(static_cast<i64>(t.pixels(0).size()) == r.pixels);
      for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) CHECK(traced(x, y) == plain(x, y));
    }
}
