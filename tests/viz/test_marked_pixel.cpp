// `why --explain` rings the pixel asked about on every frame that shows the canvas: a replay with
// the mark differs from one without only inside the ring around that pixel's cell, and on every
// such frame where the pixel is in view.
#include <cmath>

#include <catch2/catch.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "viz/replayer.hpp"
#include "viz_test_support.hpp"

using namespace scantrace;

TEST_CASE("a marked pixel is ringed on every canvas frame and nothing else changes",
          "[replay][mark]") {
  const trace::Trace t = test::record(test::medium_triangle());
  const cv::Size size(1280, 720);
  viz::Replayer plain(t, {}, size, "t"), marked(t, {}, size, "t");
  const viz::CanvasPixel p{12, 14};
  marked.mark_on_every_frame(p);
  int ringed = 0, canvas_frames = 0;
  for (std::size_t i = 0; i < plain.steps().size(); ++i) {
    INFO("step " << i + 1);
    const cv::Mat a = plain.frame(i), b = marked.frame(i);
    cv::Mat same;
    cv::inRange(a - b + (b - a), cv::Scalar(0, 0, 0), cv::Scalar(0, 0, 0), same);
    std::vector<cv::Point> changed;
    cv::findNonZero(~same, changed);
    const auto g = plain.geometry(i);
    if (!g) {
      CHECK(changed.empty());  // a card: no canvas, no ring
      continue;
    }
    ++canvas_frames;
    // The cell of pixel p, in frame coordinates, and the ring's reach around its centre.
    const cv::Point2d c = g->to_frame(static_cast<double>(p.x), static_cast<double>(p.y));
    const double reach = std::max(g->cell() / 2 + 2, 6.0) + 4;
    for (const cv::Point& q : changed) {
      REQUIRE(std::abs(q.x - c.x) <= reach + 1);
      REQUIRE(std::abs(q.y - c.y) <= reach + 1);
    }
    if (g->view().contains(cv::Point(static_cast<int>(c.x), static_cast<int>(c.y)))) {
      CHECK_FALSE(changed.empty());
      ++ringed;
    }
  }
  CHECK(canvas_frames > 10);
  CHECK(ringed == canvas_frames);  // the whole triangle is in view on every step
}
