// The magnified canvas of a frame shows each pixel written so far in the colour the trace gives
// it, and no other pixel: sampled inside the cells of the frame image, compared with the trace's
// own record of the pixel (Trace::pixel_history) converted to 8-bit BGR.
#include <catch2/catch.hpp>

#include "viz/replayer.hpp"
#include "viz_test_support.hpp"

using namespace scantrace;

namespace {

double distance_to_segment(cv::Point2d p, cv::Point2d a, cv::Point2d b) {
  const cv::Point2d d = b - a;
  const double len2 = d.dot(d);
  const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  const cv::Point2d q = a + t * d;
  return std::hypot(p.x - q.x, p.y - q.y);
}

struct Checked {
  int filled = 0, empty = 0;
};

// Compares every cell of `frame` whose sample point lies clear of the overlays (the outline,
// vertex markers and their labels, and the marks of the current row `busy_row`) with the
// trace: written pixels of rows <= `last_row` must show their traced colour, others white.
Checked check_cells(const cv::Mat& frame, const viz::ViewGeometry& g, const trace::Trace& t,
                    std::int64_t last_row, std::int64_t busy_row) {
  Checked n;
  const trace::TriangleBegin& b = t.triangle_begin(0);
  const std::vector<Vec2>& poly = b.snapped;
  const viz::PixelBox box = g.visible();
  const trace::CanvasSize canvas = t.header().canvas;
  for (std::int64_t y = std::max<std::int64_t>(box.y0, 0); y <= box.y1 && y < canvas.height; ++y)
    for (std::int64_t x = std::max<std::int64_t>(box.x0, 0); x <= box.x1 && x < canvas.width; ++x) {
      if (std::abs(y - busy_row) <= 1) continue;
      // Off the centre dot, inside the cell: a quarter cell towards its top-left corner.
      const cv::Point2d c = g.to_frame(double(x), double(y));
      const cv::Point2d s = c - cv::Point2d(g.cell() / 4, g.cell() / 4);
      const cv::Point p(int(std::lround(s.x)), int(std::lround(s.y)));
      if (!g.view().contains(p)) continue;
      bool clear = true;
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const cv::Point2d a = g.to_frame(poly[i].x, poly[i].y);
        const cv::Point2d q = g.to_frame(poly[(i + 1) % 3].x, poly[(i + 1) % 3].y);
        if (distance_to_segment(s, a, q) < 8) clear = false;
        // Vertex markers and labels stay within a few cells of their vertex.
        if (std::hypot(s.x - a.x, s.y - a.y) < 160) clear = false;
      }
      if (!clear) continue;
      const cv::Vec3b seen = frame.at<cv::Vec3b>(p);
      const trace::PixelHistory h = t.pixel_history(x, y);
      INFO("pixel (" << x << ", " << y << ")");
      if (!h.empty() && y <= last_row) {
        CHECK(test::max_channel_difference(seen, test::bgr8(h.final().color)) <= 1);
        ++n.filled;
      } else {
        CHECK(seen == cv::Vec3b(255, 255, 255));
        ++n.empty;
      }
    }
  return n;
}

std::size_t index_of(const viz::Replayer& r, viz::StepKind kind, std::int64_t row = -1) {
  for (std::size_t i = 0; i < r.steps().size(); ++i)
    if (r.steps()[i].kind == kind && (row < 0 || r.steps()[i].last_row == row)) return i;
  FAIL("no such step");
  return 0;
}

}  // namespace

TEST_CASE("filled cells carry the traced colours", "[viz][frame]") {
  const auto [shading, level] = GENERATE(std::pair{Shading::gouraud, TraceLevel::scanline},
                                         std::pair{Shading::gouraud, TraceLevel::pixel},
                                         std::pair{Shading::flat, TraceLevel::scanline});
  INFO((shading == Shading::flat ? "flat" : "gouraud")
       << ", level " << (level == TraceLevel::pixel ? "pixel" : "scanline"));
  const trace::Trace t = test::record(test::medium_triangle(), shading, level);
  viz::StepOptions o;
  o.rows_per_step = 1;
  viz::Replayer r(t, o, {1280, 720}, "test");

  // Half-way: rows 2…14 are filled, rows below are not yet.
  const std::size_t mid = index_of(r, viz::StepKind::scanlines, 14);
  const cv::Mat half = r.frame(mid);
  REQUIRE(half.type() == CV_8UC3);
  REQUIRE(half.size() == cv::Size(1280, 720));
  REQUIRE(r.geometry(mid)->cell() >= 12);
  const Checked at_mid = check_cells(half, *r.geometry(mid), t, 14, 14);
  CHECK(at_mid.filled >= 40);
  CHECK(at_mid.empty >= 100);

  // The finished triangle: every written pixel in its colour.
  const std::size_t done = index_of(r, viz::StepKind::triangle_done);
  const cv::Mat full = r.frame(done);
  const Checked at_end = check_cells(full, *r.geometry(done), t, INT64_MAX, -100);
  CHECK(at_end.filled > at_mid.filled);
}

TEST_CASE("frames are CV_8UC3 of the requested size, for every step and size", "[viz][frame]") {
  const trace::Trace t = test::record(test::small_triangle());
  for (const cv::Size size : {cv::Size(320, 180), cv::Size(1920, 1080), cv::Size(800, 800)}) {
    viz::Replayer r(t, {}, size, "test");
    for (std::size_t i = 0; i < r.steps().size(); ++i) {
      const cv::Mat f = r.frame(i);
      CHECK(f.type() == CV_8UC3);
      CHECK(f.size() == size);
    }
  }
  CHECK_THROWS_AS(viz::Replayer(t, {}, {200, 100}, "test"), std::invalid_argument);
}
