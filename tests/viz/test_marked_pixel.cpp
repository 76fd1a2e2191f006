// `why --explain` rings the pixel asked about on every frame that shows the canvas: a replay with
// the mark differs from one without, on the canvas view, only inside the ring around that pixel's
// cell, and on every such frame where the pixel is in view; beside the view, the legend says what
// the ring is. The views of the whole scene frame the traced faces around the pixel.
#include <cmath>

#include <catch2/catch.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "trace/record.hpp"
#include "viz/frame_sequence.hpp"
#include "viz/legend.hpp"
#include "viz/replayer.hpp"
#include "viz_test_support.hpp"

using namespace scantrace;

TEST_CASE("a marked pixel is ringed on every canvas frame and nothing else on the view changes",
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
    const cv::Rect view = g->view();
    for (const cv::Point& q : changed) {
      if (q.x >= view.x + view.width) continue;  // the side panel: its legend (the next test)
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

namespace {

bool has_text(const viz::Frame& f, const std::string& text) {
  for (const viz::DrawOp& op : f.ops())
    if (const auto* t = std::get_if<viz::TextOp>(&op.body); t && t->text == text) return true;
  return false;
}

}  // namespace

TEST_CASE("a replay about one pixel frames the faces around it, and its legend names the ring",
          "[replay][mark]") {
  // Three small faces near pixel (300, 200) of a 512x512 canvas, and nothing else traced (as
  // `why --explain` traces only the faces around its pixel). Their bounding box, by hand from the
  // vertices: columns 296..309, rows 195..206.
  Scene scene;
  scene.vertices = {{296, 195}, {305, 197}, {299, 204}, {309, 200}, {303, 206}};
  scene.faces = {{0, 1, 2}, {1, 3, 4}, {1, 4, 2}};
  scene.vcolors.assign(5, Color{0.2, 0.4, 0.6});
  scene.depth = {1, 2, 3, 4, 5};
  const trace::Trace t = trace::record_scene(scene, FillOptions{});
  const viz::CanvasPixel p{300, 200};
  viz::FrameSequence plain(t, {}, {1280, 720}, "t"), marked(t, {}, {1280, 720}, "t");
  marked.mark_on_every_frame(p);
  REQUIRE(plain.plan().mode == viz::ReplayMode::scene);
  const std::string ring_text = viz::legend_texts(viz::LegendKind::scene, {false, 3, true}).back();
  CHECK(ring_text == "the pixel asked about (why X Y)");
  CHECK(viz::legend_texts(viz::LegendKind::scene).back() != ring_text);
  int scene_frames = 0;
  for (std::size_t i = 0; i < plain.steps().size(); ++i) {
    INFO("step " << i + 1 << " " << viz::to_string(plain.steps()[i].kind));
    const auto g = marked.geometry(i);
    const auto whole = plain.geometry(i);
    if (!g) continue;
    REQUIRE(whole);
    // Without the mark every view of the scene shows the whole canvas; with it, the faces' box
    // with a margin of a few pixels, never the whole 512 columns.
    const viz::PixelBox v = g->visible(), w = whole->visible();
    const bool scene_view = plain.steps()[i].kind == viz::StepKind::painter_batch ||
                            plain.steps()[i].kind == viz::StepKind::scene_done;
    if (scene_view) {
      ++scene_frames;
      CHECK(w.x0 <= 0);
      CHECK(w.x1 >= 511);
    }
    CHECK(v.x0 <= 296);
    CHECK(v.x1 >= 309);
    CHECK(v.y0 <= 195);
    CHECK(v.y1 >= 206);
    CHECK(v.width() < 80);
    // The legend names the ring on every frame with a canvas view, and only when marked.
    if (plain.steps()[i].kind != viz::StepKind::title && plain.steps()[i].kind != viz::StepKind::end) {
      CHECK(has_text(marked.frame(i), ring_text));
      CHECK_FALSE(has_text(plain.frame(i), ring_text));
    }
  }
  CHECK(scene_frames >= 3);
}
