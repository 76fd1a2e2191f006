// The replay of a general polygon's trace: the canvas it rebuilds holds every inside interval of
// every row (not only the first, which is the row's `span`), in the colours the fill wrote, and
// every step of the plan composes into a frame.
#include <catch2/catch.hpp>

#include "trace/record.hpp"
#include "viz/canvas_state.hpp"
#include "viz/frame_composer.hpp"
#include "viz/legend.hpp"
#include "viz/opencv/frame_raster.hpp"
#include "viz/replay_steps.hpp"
#include "viz_test_support.hpp"

using namespace scantrace;

namespace {

trace::GeneralPolygonInput pentagram_with_hole() {
  trace::GeneralPolygonInput p;
  p.contours = {{{10, 1}, {15.5, 18.2}, {1.3, 7.3}, {18.7, 7.3}, {4.5, 18.2}},
                {{8.2, 9.1}, {11.7, 9.1}, {11.7, 12.6}, {8.2, 12.6}}};
  p.colors = {{1, 0, 0}, {0, 1, 0},       {0, 0, 1},   {1, 1, 0},      {1, 0, 1},
              {0, 1, 1}, {0.5, 0.5, 0.5}, {1, 0.5, 0}, {0.2, 0.2, 0.9}};
  p.width = 20;
  p.height = 20;
  return p;
}

}  // namespace

TEST_CASE("the replay canvas of a polygon holds every interval of every row", "[viz][polygon]") {
  for (WindingRule rule : {WindingRule::even_odd, WindingRule::non_zero}) {
    FillOptions options;
    options.winding_rule = rule;
    RgbImage image;
    const trace::Trace t = trace::record_polygon(pentagram_with_hole(), options, {}, &image);
    viz::CanvasState state(cv::Rect(0, 0, 20, 20));
    state.paint_triangle(t, 0);
    int filled = 0, rows_with_two = 0;
    for (const trace::Scanline* s : t.scanlines(0)) rows_with_two += s->intervals->size() >= 2;
    for (int y = 0; y < 20; ++y)
      for (int x = 0; x < 20; ++x) {
        INFO("pixel (" << x << ", " << y << ") rule " << to_string(rule));
        const bool written = !(image(x, y) == Rgb32f::from(Color{1, 1, 1}));
        CHECK(state.written(x, y) == written);
        if (!written) continue;
        ++filled;
        CHECK(test::max_channel_difference(state.bgr(x, y), test::bgr8(image(x, y).color())) <= 1);
      }
    CHECK(filled == t.triangle_end(0)->pixels);
    CHECK(rows_with_two > 3);  // the arms and the hole split rows into several intervals
  }
}

TEST_CASE("every step of a polygon's replay composes into a frame", "[viz][polygon]") {
  FillOptions options;
  options.winding_rule = WindingRule::non_zero;
  const trace::Trace t = trace::record_polygon(pentagram_with_hole(), options);
  const viz::StepPlan plan = viz::plan_steps(t);
  viz::FrameComposer composer(t, plan, cv::Size(960, 540), "test");
  viz::CanvasState state(cv::Rect(0, 0, 20, 20));
  for (std::size_t i = 0; i < plan.steps.size(); ++i) {
    const viz::Step& step = plan.steps[i];
    if (step.kind == viz::StepKind::scanlines)
      state.paint_rows(t, 0, step.first_row, step.last_row);
    const cv::Mat frame = viz::rasterize(composer.compose(step, i, state));
    CHECK(frame.cols == 960);
    CHECK(frame.rows == 540);
  }
}

TEST_CASE("a polygon's legend names a polygon and all of its edges", "[viz][polygon][legend]") {
  // A five-edge star: not "triangle outline", not "edges e0, e1, e2" (issue 20).
  const std::vector<std::string> star =
      viz::legend_texts(viz::LegendKind::triangle, {.polygon = true, .edges = 5});
  CHECK(std::find(star.begin(), star.end(), "polygon outline (snapped)") != star.end());
  CHECK(std::find(star.begin(), star.end(), "edges e0 .. e4 (bold: active)") != star.end());
  for (const std::string& text : star) {
    CHECK_THAT(text, !Catch::Contains("triangle"));
    CHECK_THAT(text, !Catch::Contains("e0, e1, e2"));
  }
  // A triangle's legend is unchanged.
  const std::vector<std::string> triangle = viz::legend_texts(viz::LegendKind::triangle);
  CHECK(std::find(triangle.begin(), triangle.end(), "triangle outline (snapped)") !=
        triangle.end());
  CHECK(std::find(triangle.begin(), triangle.end(), "edges e0, e1, e2 (bold: active)") !=
        triangle.end());
}
