// The course report's example, (20,20), (250,80), (300,400) red/green/blue, read back from its
// trace: active edges, their exact x, the span and its colours at chosen rows, all derived here
// from the geometry alone.
#include <catch2/catch.hpp>

#include "trace/record.hpp"

using namespace scantrace;
using namespace scantrace::trace;

namespace {

struct Line {  // the edge (x0,y0)→(x1,y1) and the colours at its ends
  double x0, y0, x1, y1;
  Color c0, c1;
  double x_at(double y) const { return x0 + (x1 - x0) * (y - y0) / (y1 - y0); }
  Color color_at(double y) const {
    const double s = (y - y0) / (y1 - y0);
    return c0 * (1 - s) + c1 * s;
  }
};

// ceil((a + b·k) / d) for integers, d > 0: the exact first pixel at or after an intersection.
long long ceil_div(long long num, long long den) {
  return num >= 0 ? (num + den - 1) / den : -((-num) / den);
}

const Color kRed{1, 0, 0}, kGreen{0, 1, 0}, kBlue{0, 0, 1};
const Line kEdge0{20, 20, 250, 80, kRed, kGreen};     // v0 → v1
const Line kEdge1{250, 80, 300, 400, kGreen, kBlue};  // v1 → v2
const Line kEdge2{20, 20, 300, 400, kRed, kBlue};     // v0 → v2 (edge 2 runs v2 → v0)

// Barycentric colour at (x, y): independent of the edge-then-span construction.
Color barycentric(double x, double y) {
  auto area = [](double ax, double ay, double bx, double by, double cx, double cy) {
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  };
  const double total = area(20, 20, 250, 80, 300, 400);
  const double w0 = area(x, y, 250, 80, 300, 400) / total;
  const double w1 = area(20, 20, x, y, 300, 400) / total;
  const double w2 = 1 - w0 - w1;
  return kRed * w0 + kGreen * w1 + kBlue * w2;
}

void check_color(Color got, Color want) {
  CHECK(got.r == Approx(want.r).margin(1e-9));
  CHECK(got.g == Approx(want.g).margin(1e-9));
  CHECK(got.b == Approx(want.b).margin(1e-9));
}

}  // namespace

TEST_CASE("course example: scanline records equal the geometry", "[trace][course]") {
  const Trace trace =
      record_triangle({{Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}}, {kRed, kGreen, kBlue}},
                      FillOptions{.shading = Shading::gouraud});
  REQUIRE(trace.triangles() == std::vector<int>{0});

  for (long long y : {20LL, 21LL, 50LL, 79LL, 80LL, 81LL, 200LL, 333LL, 399LL}) {
    CAPTURE(y);
    const Scanline& row = trace.scanline(0, y);
    // Rows 20…79 lie between edge 0 and edge 2; from row 80 (where v1 is) edge 1 replaces edge 0.
    const Line& right = y < 80 ? kEdge0 : kEdge1;
    const int right_id = y < 80 ? 0 : 1;
    REQUIRE(row.active_edges.size() == 2);
    CHECK(row.active_edges[0].edge == 2);
    CHECK(row.active_edges[1].edge == right_id);
    CHECK(row.active_edges[0].x == Approx(kEdge2.x_at(y)).epsilon(1e-15));
    CHECK(row.active_edges[1].x == Approx(right.x_at(y)).epsilon(1e-15));

    REQUIRE(row.active_points.size() == 2);
    check_color(row.active_points[0].color, kEdge2.color_at(y));
    check_color(row.active_points[1].color, right.color_at(y));

    // Exact span ends from integer arithmetic: x = (x0·Δy + Δx·(y − y0)) / Δy.
    const long long begin = ceil_div(20 * 380 + 280 * (y - 20), 380);
    const long long end =
        y < 80 ? ceil_div(20 * 60 + 230 * (y - 20), 60) : ceil_div(250 * 320 + 50 * (y - 80), 320);
    if (begin < end) {
      REQUIRE(row.span.has_value());
      CHECK(row.span->x_begin == begin);
      CHECK(row.span->x_end == end);
      REQUIRE(row.span_colors.has_value());
      check_color(row.span_colors->begin, barycentric(static_cast<double>(begin), y));
      check_color(row.span_colors->end, barycentric(static_cast<double>(end - 1), y));
    } else {
      CHECK_FALSE(row.span.has_value());
    }
  }
  // Row 20 is the apex: both edges start at x = 20, the span is empty.
  CHECK_FALSE(trace.scanline(0, 20).span.has_value());
  CHECK(trace.scanline(0, 20).entered == std::vector<int>{0, 2});
  CHECK(trace.scanline(0, 80).retired == std::vector<int>{0});
  CHECK(trace.scanline(0, 80).entered == std::vector<int>{1});
  // Rows 20 … 399: y = 400 (the bottom vertex) belongs to the half-open rule's next row.
  CHECK(trace.scanlines(0).size() == 380);
  CHECK_FALSE(trace.has_scanline(0, 400));
}

TEST_CASE("course example: the edge table", "[trace][course]") {
  const Trace trace = record_triangle(
      {{Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}}, {kRed, kGreen, kBlue}}, FillOptions{});
  const EdgeTableEvent& table = trace.edge_table(0);
  REQUIRE(table.edges.size() == 3);
  CHECK(table.horizontal.empty());
  // Sorted by first row: edges 0 and 2 start at y = 20, edge 1 at y = 80.
  CHECK(table.edges[0].edge == 0);
  CHECK(table.edges[1].edge == 2);
  CHECK(table.edges[2].edge == 1);
  const EdgeEntry& e2 = table.edges[1];
  CHECK(e2.from == Vec2{300, 400});
  CHECK(e2.to == Vec2{20, 20});
  CHECK(e2.y_min == 20);
  CHECK(e2.y_max == 400);
  CHECK(e2.x_at_y_min == 20);
  CHECK(e2.dx_dy == Approx(280.0 / 380.0));
  CHECK(e2.first_row == 20);
  CHECK(e2.last_row == 399);
  CHECK(table.edges[0].dx_dy == Approx(230.0 / 60.0));
  CHECK(table.edges[0].last_row == 79);
  CHECK(table.edges[2].first_row == 80);
}
