// Convex polygons narrate themselves through the same fill: all their edges in the edge table,
// two active edges per row, spans equal to the pixels written.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "src/scanline_fill.hpp"
#include "trace/event_tracer.hpp"
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
    for (const ActivePoint& p : s->active_points) {
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
