// The last frame of a replay shows exactly the rendered image, whatever the visibility rule (the
// painter's algorithm or the z-buffer) and whatever the trace level (triangle, scanline, pixel):
// the canvas area of the frame is read back, cell by cell, and compared with the image the traced
// render itself produced (record_scene's image, converted to 8-bit as a PNG would be). And the
// cards name the rule that was used.
#include <algorithm>
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "src/painter.hpp"
#include "trace/record.hpp"
#include "viz/cards.hpp"
#include "viz/replayer.hpp"

using namespace scantrace;

namespace {

// Two triangles passing through each other (face 1 is nearer right of x = 27 only) and a third,
// farther one behind both: the painter's algorithm draws face 1 over face 0 whole, the z-buffer
// shows the seam. A non-white background, so that unwritten pixels are checked too.
Scene crossing_scene() {
  Scene s;
  s.width = 50;
  s.height = 40;
  s.background = {0.9, 0.95, 0.8};
  s.vertices = {{5, 5}, {5, 38}, {45, 5}, {45, 5}, {5, 5}, {45, 38}, {0, 20}, {49, 25}, {20, 39}};
  s.depth = {0, 0, 2, 0.2, 2.2, 0.2, 5, 5, 5};
  s.vcolors = {{0, 0, 1}, {0, 0.5, 1}, {0, 0, 1},   {1, 0, 0},  {1, 0.3, 0},
               {1, 0, 0}, {0, 1, 0},   {0, 1, 0.5}, {0.2, 1, 0}};
  s.faces = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  return s;
}

cv::Vec3b png_bgr(const Rgb32f& p) {
  return {to_byte(p.b), to_byte(p.g), to_byte(p.r)};
}

// Cells whose sample point (a quarter cell off the centre dot, clear of the grid lines) shows
// something else than the rendered pixel.
int differing_cells(const cv::Mat& frame, const viz::ViewGeometry& g, const RgbImage& image) {
  int differing = 0, checked = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const cv::Point2d s =
          g.to_frame(double(x), double(y)) - cv::Point2d(g.cell() / 4, g.cell() / 4);
      const cv::Point p(int(std::lround(s.x)), int(std::lround(s.y)));
      REQUIRE(g.view().contains(p));
      ++checked;
      if (frame.at<cv::Vec3b>(p) != png_bgr(image(x, y))) {
        if (differing < 5)
          WARN("pixel (" << x << ", " << y << "): frame " << frame.at<cv::Vec3b>(p) << ", render "
                         << png_bgr(image(x, y)));
        ++differing;
      }
    }
  CHECK(checked == image.width() * image.height());
  return differing;
}

}  // namespace

TEST_CASE(
    "the last frame of a scene replay is the render, for both visibility rules and every level",
    "[viz][render]") {
  const Scene scene = crossing_scene();
  const auto visibility = GENERATE(Visibility::painter, Visibility::zbuffer);
  const auto shading = GENERATE(Shading::gouraud, Shading::flat);
  const auto level = GENERATE(TraceLevel::triangle, TraceLevel::scanline, TraceLevel::pixel);
  FillOptions o;
  o.visibility = visibility;
  o.shading = shading;
  trace::TraceFilter f;
  f.level = level;
  RgbImage image;
  const trace::Trace t = trace::record_scene(scene, o, f, &image);
  viz::StepOptions so;
  so.mode = viz::ReplayMode::scene;
  viz::Replayer r(t, so, {1280, 720}, "test");
  const std::size_t last = r.steps().size() - 1;
  REQUIRE(r.steps()[last].kind == viz::StepKind::end);
  const cv::Mat frame = r.frame(last);
  INFO(to_string(visibility) << ", " << to_string(shading) << ", level "
                             << trace::to_string(level));
  CHECK(differing_cells(frame, *r.geometry(last), image) == 0);

  // The cards say which rule made the picture, and only that one.
  std::string recap;
  for (const std::string& line : viz::recap_lines(t, r.plan())) recap += line + "\n";
  if (visibility == Visibility::zbuffer) {
    CHECK(viz::visibility_rule(t.header()).find("z-buffer") != std::string::npos);
    CHECK(recap.find("depth stored there") != std::string::npos);
    CHECK(recap.find("largest depth first") == std::string::npos);
  } else {
    CHECK(viz::visibility_rule(t.header()).find("painter") != std::string::npos);
    CHECK(recap.find("largest depth first") != std::string::npos);
    CHECK(recap.find("depth stored") == std::string::npos);
  }
}

TEST_CASE("the z-buffer scene differs from its painter's render (the test above can fail)",
          "[viz][render]") {
  const Scene scene = crossing_scene();
  FillOptions painter, zbuffer;
  zbuffer.visibility = Visibility::zbuffer;
  const RgbImage a = render(scene, painter), b = render(scene, zbuffer);
  int differing = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) differing += !(a(x, y) == b(x, y));
  CHECK(differing > 20);
}

TEST_CASE("the last frame of a one-triangle replay is the render at every level", "[viz][render]") {
  trace::TriangleInput in;
  in.vertices = {Vec2{2.3, 1.2}, Vec2{29, 9.5}, Vec2{8, 27.6}};
  in.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  in.width = 32;
  in.height = 30;
  const auto level = GENERATE(TraceLevel::triangle, TraceLevel::scanline, TraceLevel::pixel);
  trace::TraceFilter f;
  f.level = level;
  RgbImage image;
  const trace::Trace t = trace::record_triangle(in, FillOptions{}, f, &image);
  viz::Replayer r(t, {}, {1280, 720}, "test");
  const std::size_t last = r.steps().size() - 1;
  const cv::Mat frame = r.frame(last);
  const viz::ViewGeometry g = *r.geometry(last);
  // The end card of one triangle shows the region around it, with its vertex markers on top:
  // compare the cells clear of them.
  int differing = 0, compared = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      bool near_vertex = false;
      for (const Vec2& v : in.vertices)
        near_vertex = near_vertex || std::hypot(v.x - x, v.y - y) < 8;  // marker and label
      const cv::Point2d s =
          g.to_frame(double(x), double(y)) - cv::Point2d(g.cell() / 4, g.cell() / 4);
      const cv::Point p(int(std::lround(s.x)), int(std::lround(s.y)));
      if (near_vertex || !g.view().contains(p)) continue;
      ++compared;
      if (frame.at<cv::Vec3b>(p) != png_bgr(image(x, y))) {
        WARN("pixel (" << x << ", " << y << "): frame " << frame.at<cv::Vec3b>(p) << ", render "
                       << png_bgr(image(x, y)));
        ++differing;
      }
    }
  INFO("level " << trace::to_string(level));
  CHECK(compared > 500);
  CHECK(differing == 0);
}
