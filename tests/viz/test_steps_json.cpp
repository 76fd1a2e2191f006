// web/step_json.hpp's StepsJson: the list of a replay's steps the explorer's module writes on
// every mouse move of a drag, written directly, must be the text of nlohmann's objects
// (step_json(s, i).dump(), the form the trace page's module writes) for every step.
#include <catch2/catch.hpp>

#include "trace/record.hpp"
#include "viz/frame_sequence.hpp"
#include "web/step_json.hpp"

using namespace scantrace;

namespace {

std::string by_nlohmann(const viz::FrameSequence& s) {
  std::string out = "[";
  for (std::size_t i = 0; i < s.steps().size(); ++i)
    out += (i ? "," : "") + web::step_json(s, i).dump();
  return out + "]";
}

trace::Trace triangle(std::array<Vec2, 3> v, int width = 512, int height = 512) {
  return trace::record_triangle({v, {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}}, width, height}, {});
}

}  // namespace

TEST_CASE("the steps' JSON written directly is nlohmann's, step by step") {
  trace::GeneralPolygonInput star;
  star.contours = {{Vec2{256, 40}, Vec2{380, 440}, Vec2{60, 190}, Vec2{450, 190}, Vec2{130, 440}}};
  star.colors.assign(5, Color{0.25, 0.5, 1});
  const std::vector<trace::Trace> traces = {
      triangle({Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}}),
      triangle({Vec2{20, 20}, Vec2{250, 80}, Vec2{283.796875, 389.9921875}}),
      // Cut by the canvas's edges (a view of negative origin), and a sliver of one row.
      triangle({Vec2{-40.3, 30}, Vec2{300, -20.5}, Vec2{530.75, 600}}),
      triangle({Vec2{2, 5}, Vec2{60, 5.25}, Vec2{30, 5.5}}, 64, 48),
      trace::record_polygon(star, {}),
  };
  int steps = 0;
  for (const trace::Trace& t : traces)
    for (const viz::Size size : {viz::Size{688, 387}, viz::Size{1280, 720}, viz::Size{320, 180}})
      for (const int rows : {0, 1, 7}) {
        viz::StepOptions o;
        o.rows_per_step = rows;
        const viz::FrameSequence s(t, o, size, "test");
        CAPTURE(size.width, rows);
        CHECK(web::StepsJson()(s) == by_nlohmann(s));
        steps += static_cast<int>(s.steps().size());
      }
  CHECK(steps > 1000);
}

TEST_CASE("one StepsJson writes each sequence's own steps") {
  // Its cached geometry text must not leak from one sequence into the next.
  web::StepsJson json;
  const trace::Trace a = triangle({Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}});
  const trace::Trace b = triangle({Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}}, 300, 200);
  const viz::FrameSequence sa(a, {}, {688, 387}, "a"), sb(b, {}, {688, 387}, "b");
  CHECK(json(sa) == by_nlohmann(sa));
  CHECK(json(sb) == by_nlohmann(sb));
  CHECK(json(sa) == by_nlohmann(sa));
}
