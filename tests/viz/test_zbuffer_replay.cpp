// Replaying a z-buffered render: pixels the depth test rejected were narrated but not written, so
// the replayed canvas must equal the rendered image, not a painter's overwrite.
#include <catch2/catch.hpp>

#include <opencv2/core.hpp>

#include "trace/record.hpp"
#include "viz/canvas_state.hpp"

using namespace scantrace;

TEST_CASE("replayed canvas of a z-buffer pixel trace equals the render", "[viz][zbuffer]") {
  // Two triangles passing through each other; face 1 is nearer right of x = 27 only.
  Scene s;
  s.width = s.height = 50;
  s.vertices = {{5, 5}, {5, 45}, {45, 5}, {45, 5}, {5, 5}, {45, 45}};
  s.depth = {0, 0, 2, 0.2, 2.2, 0.2};
  s.vcolors = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  s.faces = {{0, 1, 2}, {3, 4, 5}};
  FillOptions o;
  o.visibility = Visibility::zbuffer;
  trace::TraceFilter f;
  f.level = TraceLevel::pixel;
  RgbImage image;
  const trace::Trace t = trace::record_scene(s, o, f, &image);
  viz::CanvasState canvas(cv::Rect(0, 0, 50, 50));
  canvas.paint_triangle(t, 0);
  canvas.paint_triangle(t, 1);
  long rejected_seen = 0;
  for (const trace::Pixel* p : t.pixels(1)) rejected_seen += !p->depth_test->passed;
  CHECK(rejected_seen > 0);
  // Every pixel, not only those the replay marks written (a replay that paints nothing must
  // fail): unwritten ones are background in the render, written ones have its colour.
  long written = 0;
  for (int y = 0; y < 50; ++y)
    for (int x = 0; x < 50; ++x) {
      INFO(x << "," << y);
      if (!canvas.written(x, y)) {
        CHECK(image(x, y) == Rgb32f::from(s.background));
        continue;
      }
      ++written;
      const Color c = image(x, y).color();
      const cv::Vec3b want(static_cast<unsigned char>(c.b * 255 + 0.5),
                           static_cast<unsigned char>(c.g * 255 + 0.5),
                           static_cast<unsigned char>(c.r * 255 + 0.5));
      CHECK(canvas.bgr(x, y) == want);
    }
  CHECK(written > 100);
}
