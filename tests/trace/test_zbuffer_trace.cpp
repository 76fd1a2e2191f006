// The pixel-level trace of a z-buffer render: every pixel the fill writes is narrated with its
// depth test, rejected pixels leave the image as it was, and culled faces are reported.
#include <catch2/catch.hpp>
#include <sstream>

#include "trace/event_json.hpp"
#include "trace/record.hpp"

using namespace scantrace;
using namespace scantrace::trace;

namespace {

// Two triangles passing through each other (as in tests/core/test_models.cpp): face 0 (blue)
// has depth (x − 50)/200, face 1 (red) (450 − x)/200 + 0.2; they cross at x = 270.
Scene interpenetrating() {
  Scene s;
  s.width = s.height = 500;
  s.vertices = {{50, 50}, {50, 450}, {450, 50}, {450, 50}, {50, 50}, {450, 450}};
  s.depth = {0, 0, 2, 0.2, 2.2, 0.2};
  s.vcolors = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  s.faces = {{0, 1, 2}, {3, 4, 5}};
  return s;
}

}  // namespace

TEST_CASE("z-buffer pixel trace records depth-test rejections", "[trace][zbuffer]") {
  FillOptions o;
  o.visibility = Visibility::zbuffer;
  for (Shading shading : {Shading::flat, Shading::gouraud}) {
    o.shading = shading;
    TraceFilter f;
    f.level = TraceLevel::pixel;
    f.rows = RowRange::parse("60:60");
    RgbImage image;
    const Trace t = record_scene(interpenetrating(), o, f, &image);
    long rejected = 0, passed = 0;
    for (const Event& e : t.events()) {
      const auto* p = std::get_if<Pixel>(&e);
      if (!p) continue;
      REQUIRE(p->depth_test);
      const double own = p->triangle == 0 ? (p->x - 50) / 200.0 : (450 - p->x) / 200.0 + 0.2;
      CHECK(p->depth_test->depth == Approx(own).margin(1e-12));
      if (p->triangle == 0) {
        // Drawn first: the buffer was empty, everything passes.
        CHECK(p->depth_test->passed);
        CHECK_FALSE(p->depth_test->stored);
      } else if (p->x >= 60 && p->x < 440) {
        // Face 1 over face 0's row 60 (x in 60…439 is inside both): rejected left of x = 270.
        REQUIRE(p->depth_test->stored);
        CHECK(*p->depth_test->stored == Approx((p->x - 50) / 200.0).margin(1e-12));
        CHECK(p->depth_test->passed == (p->x > 270));
      }
      (p->depth_test->passed ? passed : rejected) += 1;
      // A rejected pixel keeps the colour of the nearer face; a passed one is the face's.
      const Color c = image(static_cast<int>(p->x), static_cast<int>(p->y)).color();
      if (p->triangle == 1 && !p->depth_test->passed) CHECK(c == Color{0, 0, 1});
    }
    // Row 60: face 1 spans x 60…449 and is rejected on x = 60…270 (211 pixels; x = 270 is a
    // tie, which the face drawn first keeps).
    CHECK(rejected == 211);
    CHECK(passed > 0);
  }
}

TEST_CASE("the JSON of a depth-tested pixel round-trips", "[trace][zbuffer]") {
  Pixel p{1, 3, 4, {0.5, 0.25, 1}, 0.5, PixelDepthTest{false, 1.5, 0.75}};
  const nlohmann::ordered_json j = event_to_json(Event{p});
  const Event back = event_from_json(nlohmann::json::parse(j.dump()));
  const auto& q = std::get<Pixel>(back);
  REQUIRE(q.depth_test);
  CHECK_FALSE(q.depth_test->passed);
  CHECK(q.depth_test->depth == 1.5);
  CHECK(q.depth_test->stored == 0.75);
  CHECK(j.dump().find("\"depth_test\":\"rejected\"") != std::string::npos);
}

TEST_CASE("culled faces are traced as triangle_skipped with reason culled", "[trace][zbuffer]") {
  Scene s = interpenetrating();
  s.faces.push_back({3, 5, 4});  // face 1 reversed: clockwise on screen, a back face
  FillOptions o;
  o.cull = Cull::back;
  const Trace t = record_scene(s, o);
  int culled = 0;
  for (const Event& e : t.events())
    if (const auto* k = std::get_if<TriangleSkipped>(&e)) {
      CHECK(k->triangle == 2);
      CHECK(k->reason == "culled");
      ++culled;
    }
  CHECK(culled == 1);
  // The header says how the render was made; the course's defaults are left out.
  CHECK(t.header().cull == Cull::back);
  CHECK(t.header().visibility == Visibility::painter);
  const std::string line = event_to_json(Event{t.header()}).dump();
  CHECK(line.find("\"cull\":\"back\"") != std::string::npos);
  CHECK(line.find("visibility") == std::string::npos);
}
