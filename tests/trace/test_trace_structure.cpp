// Structure of the narration: horizontal edges, entered/retired bookkeeping, skipped triangles.
#include <catch2/catch.hpp>
#include <random>
#include <set>

#include "trace/record.hpp"

using namespace scantrace;
using namespace scantrace::trace;

namespace {

const std::array<Color, 3> kRgb{Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};

Trace trace_of(std::array<Vec2, 3> v, FillOptions options = {}) {
  return record_triangle({v, kRgb, 64, 64}, options);
}

// Replays entered/retired from row to row and checks it against the active edges on each row.
void check_bookkeeping(const Trace& trace, int t) {
  std::set<int> active;
  for (const Scanline* s : trace.scanlines(t)) {
    CAPTURE(s->y);
    for (int e : s->retired) CHECK(active.erase(e) == 1);
    for (int e : s->entered) CHECK(active.insert(e).second);
    std::set<int> listed;
    for (const trace::EdgeCrossing& a : s->active_edges) listed.insert(a.edge);
    CHECK(listed == active);
    for (std::size_t i = 1; i < s->active_points.size(); ++i)
      CHECK(s->active_points[i - 1].x <= s->active_points[i].x);
  }
}

}  // namespace

TEST_CASE("horizontal edges are listed aside and never active", "[trace]") {
  // Edge 0 (v0→v1) is a horizontal top edge, edge 2 (v2→v0)… of the second, a horizontal bottom.
  for (auto v : {std::array<Vec2, 3>{Vec2{10, 10}, Vec2{50, 10}, Vec2{30, 40}},
                 std::array<Vec2, 3>{Vec2{30, 5}, Vec2{50, 30}, Vec2{10, 30}}}) {
    const Trace trace = trace_of(v);
    const EdgeTableEvent& table = trace.edge_table(0);
    REQUIRE(table.horizontal.size() == 1);
    REQUIRE(table.edges.size() == 2);
    const int flat_edge = table.horizontal[0].edge;
    CHECK(v[flat_edge].y == v[(flat_edge + 1) % 3].y);
    CHECK(table.horizontal[0].y == v[flat_edge].y);
    for (const Scanline* s : trace.scanlines(0))
      for (const trace::EdgeCrossing& a : s->active_edges) CHECK(a.edge != flat_edge);
    check_bookkeeping(trace, 0);
  }
}

TEST_CASE("entered and retired are consistent from row to row", "[trace]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> pos(-10.0, 74.0);
  for (int i = 0; i < 300; ++i) {
    std::array<Vec2, 3> v;
    for (auto& p : v) p = {std::round(pos(rng) * 2) / 2, std::round(pos(rng) * 2) / 2};
    for (FillRule rule : {FillRule::top_left, FillRule::closed}) {
      const Trace trace = trace_of(v, FillOptions{.fill_rule = rule});
      if (trace.skipped(0)) continue;
      check_bookkeeping(trace, 0);
    }
  }
}

TEST_CASE("triangles that fill nothing are reported as skipped, with the reason", "[trace]") {
  CHECK(trace_of({Vec2{5, 5}, Vec2{20, 20}, Vec2{35, 35}}).skipped(0)->reason == "degenerate");
  CHECK(trace_of({Vec2{5, 5}, Vec2{5, 5}, Vec2{30, 9}}).skipped(0)->reason == "degenerate");
  CHECK(trace_of({Vec2{100, 5}, Vec2{120, 5}, Vec2{110, 30}}).skipped(0)->reason == "offscreen");
  const Trace t = trace_of({Vec2{5, 5}, Vec2{20, 20}, Vec2{35, 35}});
  CHECK(t.scanlines(0).empty());
  CHECK_FALSE(t.triangle_end(0).has_value());
}
