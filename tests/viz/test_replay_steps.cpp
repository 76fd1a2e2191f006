// The steps a replay shows: one per set-up item, per scanline (or group) and per card, and for a
// scene batches of triangles in drawing order.
#include <catch2/catch.hpp>

#include "src/scene.hpp"
#include "viz/replay.hpp"
#include "viz/replay_steps.hpp"
#include "viz/step_label.hpp"
#include "viz_test_support.hpp"

using namespace scantrace;
using viz::StepKind;

namespace {

std::size_t count(const viz::StepPlan& plan, StepKind kind) {
  return static_cast<std::size_t>(std::count_if(
      plan.steps.begin(), plan.steps.end(), [&](const viz::Step& s) { return s.kind == kind; }));
}

// A strip of `n` thin triangles side by side at increasing depth, so the painter's order is the
// reverse of the face order.
Scene strip(int n) {
  Scene s;
  s.width = 512;
  s.height = 512;
  for (int i = 0; i < n; ++i) {
    const double x = (i % 500) + 1.0, y = 1.0 + (i / 500) * 25;
    const int v = static_cast<int>(s.vertices.size());
    s.vertices.insert(s.vertices.end(), {{x, y}, {x + 5, y + 2}, {x + 1, y + 20}});
    s.vcolors.insert(s.vcolors.end(), {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    s.depth.insert(s.depth.end(), {double(i), double(i), double(i)});
    s.faces.push_back({v, v + 1, v + 2});
  }
  return s;
}

}  // namespace

TEST_CASE("one step per edge-table entry and per scanline, plus set-up and cards", "[viz][steps]") {
  const trace::Trace t = test::record(test::small_triangle());
  viz::StepOptions o;
  o.rows_per_step = 1;
  const viz::StepPlan plan = viz::plan_steps(t, o);
  CHECK(plan.mode == viz::ReplayMode::triangles);
  // Rows ceil(1.2) = 2 … ceil(11.6) - 1 = 11, three non-horizontal edges.
  CHECK(count(plan, StepKind::scanlines) == 10);
  CHECK(count(plan, StepKind::edge_table_entry) == 3);
  CHECK(count(plan, StepKind::triangle_setup) == 1);
  CHECK(count(plan, StepKind::triangle_done) == 1);
  REQUIRE(plan.steps.size() == 1 + 1 + 3 + 10 + 1 + 1);
  CHECK(plan.steps.front().kind == StepKind::title);
  CHECK(plan.steps.back().kind == StepKind::end);
  std::int64_t y = 2;
  for (const viz::Step& s : plan.steps)
    if (s.kind == StepKind::scanlines) {
      CHECK(s.first_row == y);
      CHECK(s.last_row == y);
      CHECK(s.scanline_count == 10);
      ++y;
    }
}

TEST_CASE("grouped scanlines cover every row once, edge changes get their own step",
          "[viz][steps]") {
  trace::TriangleInput big;
  big.vertices = {Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}};
  big.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  const trace::Trace t = test::record(big);
  for (int max_steps : {5, 40, 1000}) {
    viz::StepOptions o;
    o.max_scanline_steps = max_steps;
    const viz::StepPlan plan = viz::plan_steps(t, o);
    const std::size_t group = (380 + max_steps - 1) / max_steps;
    std::int64_t next = 20;
    std::size_t steps = 0, changing = 0;
    for (const viz::Step& s : plan.steps) {
      if (s.kind != StepKind::scanlines) continue;
      ++steps;
      INFO("max " << max_steps << ", rows " << s.first_row << ".." << s.last_row);
      CHECK(s.first_row == next);
      CHECK(static_cast<std::size_t>(s.last_row - s.first_row + 1) <= group);
      const trace::Scanline& first = t.scanline(0, s.first_row);
      if (!first.entered.empty() || !first.retired.empty()) {
        ++changing;
        CHECK(s.first_row == s.last_row);
      }
      for (std::int64_t r = s.first_row + 1; r <= s.last_row; ++r) {
        CHECK(t.scanline(0, r).entered.empty());
        CHECK(t.scanline(0, r).retired.empty());
      }
      next = s.last_row + 1;
    }
    CHECK(next == 400);  // rows 20 … 399
    // Each row that changes the active edge table is a step and may cut a group in two.
    CHECK(steps <= static_cast<std::size_t>(max_steps) + 2 * changing);
  }
}

TEST_CASE("the default demo triangle video is under a minute", "[viz][steps]") {
  trace::TriangleInput demo;
  demo.vertices = {Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}};
  demo.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  const trace::Trace t = test::record(demo);
  const viz::ReplayOptions defaults;
  const viz::StepPlan plan = viz::plan_steps(t, defaults.plan);
  double seconds = 0;
  for (const viz::Step& s : plan.steps)
    seconds += viz::frames_for(s, defaults.fps, defaults.hold) / defaults.fps;
  CHECK(count(plan, StepKind::scanlines) >= 30);
  CHECK(count(plan, StepKind::scanlines) <= 90);
  CHECK(seconds < 60);
  CHECK(seconds > 20);
}

TEST_CASE("a scene replays as the painter's algorithm in a bounded number of steps",
          "[viz][steps]") {
  for (int n : {3, 250, 10000}) {
    const Scene scene = strip(n);
    const trace::Trace t = trace::record_scene(scene, FillOptions{});
    const viz::StepPlan plan = viz::plan_steps(t);
    INFO(n << " triangles");
    CHECK(plan.mode == viz::ReplayMode::scene);
    REQUIRE(plan.order.size() == static_cast<std::size_t>(n));
    // Drawing order is far to near: the deepest (last) face first.
    CHECK(plan.order.front() == n - 1);
    CHECK(plan.order.back() == 0);
    std::size_t next = 0, batches = 0;
    for (const viz::Step& s : plan.steps)
      if (s.kind == StepKind::painter_batch) {
        CHECK(s.first == next);
        CHECK(s.triangle == plan.order[s.last]);
        next = s.last + 1;
        ++batches;
      }
    CHECK(next == plan.order.size());
    CHECK(batches <= 100);
    if (n <= 100) CHECK(batches == static_cast<std::size_t>(n));
    CHECK(count(plan, StepKind::scene_done) == 1);
    const viz::ReplayOptions defaults;
    std::size_t frames = 0;
    for (const viz::Step& s : plan.steps)
      frames += static_cast<std::size_t>(viz::frames_for(s, defaults.fps, defaults.hold));
    CHECK(frames <= 300);
  }
}

TEST_CASE(
    "a painter's step label names positions in the drawing order, then the face it highlights",
    "[viz][steps]") {
  // In strip(n) the face drawn at position p (0-based) is face n-1-p, so positions and face
  // numbers differ everywhere but the middle: a label mixing them up cannot pass.
  const int n = 250;
  const trace::Trace t = trace::record_scene(strip(n), FillOptions{});
  const viz::StepPlan plan = viz::plan_steps(t);
  int batches = 0;
  for (const viz::Step& s : plan.steps) {
    if (s.kind != StepKind::painter_batch) continue;
    ++batches;
    const auto first = static_cast<int>(s.first) + 1, last = static_cast<int>(s.last) + 1;
    const std::string expected = "painter: drawn " + std::to_string(first) + "-" +
                                 std::to_string(last) + " of " + std::to_string(n) +
                                 " (highlighted: triangle " + std::to_string(n - last) + ")";
    CHECK(viz::step_label(plan, s) == expected);
  }
  CHECK(batches > 1);
}

TEST_CASE("step ranges", "[viz][steps]") {
  using R = viz::StepRange;
  CHECK(R::parse("3:7").first == 3);
  CHECK(R::parse("3:7").last == 7);
  CHECK(R::parse(":5").first == 1);
  CHECK(R::parse(":5").last == 5);
  CHECK(R::parse("4:").first == 4);
  CHECK(R::parse("4:").last == SIZE_MAX);
  CHECK(R::parse("9").first == 9);
  CHECK(R::parse("9").last == 9);
  for (const char* bad : {"0:3", "5:2", "a:b", ":", "", "3:x", "-1:4"})
    CHECK_THROWS_AS(R::parse(bad), std::invalid_argument);
}
