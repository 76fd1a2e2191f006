// record_triangle_onto / record_polygon_onto (trace/record.hpp): the fill drawn onto the caller's
// canvas as it is, what the explorer's module does on every mouse move of a drag.
#include <catch2/catch.hpp>

#include "trace/event_json.hpp"
#include "trace/record.hpp"

using namespace scantrace;
using namespace scantrace::trace;

namespace {

std::vector<std::string> lines(const Trace& t) {
  std::vector<std::string> out;
  for (const Event& e : t.events()) out.push_back(event_to_json(e).dump());
  return out;
}

const TriangleInput kTriangle{{Vec2{3.5, 2}, Vec2{40, 9.25}, Vec2{20, 37}},
                              {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}},
                              48,
                              40,
                              Color{0.2, 0.3, 0.4}};

}  // namespace

TEST_CASE("a triangle recorded onto a canvas of its background is the one recorded alone") {
  RgbImage alone;
  const Trace want = record_triangle(kTriangle, {}, {}, &alone);
  RgbImage canvas(48, 40, Rgb32f::from(kTriangle.background));
  const Trace got = record_triangle_onto(canvas, kTriangle, {});
  CHECK(lines(got) == lines(want));
  CHECK(canvas == alone);
}

TEST_CASE("a polygon recorded onto a canvas of its background is the one recorded alone") {
  GeneralPolygonInput p;
  p.contours = {{Vec2{2, 2}, Vec2{30, 4}, Vec2{26, 30}, Vec2{4, 28}}, {Vec2{10, 10}, Vec2{18, 11}, Vec2{14, 20}}};
  p.colors.assign(7, Color{0.5, 0.25, 1});
  p.width = 32;
  p.height = 32;
  FillOptions o;
  o.winding_rule = WindingRule::non_zero;
  RgbImage alone;
  const Trace want = record_polygon(p, o, {}, &alone);
  RgbImage canvas(32, 32, Rgb32f::from(p.background));
  CHECK(lines(record_polygon_onto(canvas, p, o)) == lines(want));
  CHECK(canvas == alone);
}

TEST_CASE("a canvas recorded onto is drawn on as it is, not cleared") {
  RgbImage canvas(48, 40, Rgb32f::from(kTriangle.background));
  const Rgb32f marker{0.5f, 0.5f, 0.5f};
  canvas(0, 39) = marker;  // outside the triangle
  record_triangle_onto(canvas, kTriangle, {});
  CHECK(canvas(0, 39) == marker);
}

TEST_CASE("a canvas of another size than the input's is refused before anything is drawn") {
  RgbImage canvas(47, 40, Rgb32f{});
  CHECK_THROWS_AS(record_triangle_onto(canvas, kTriangle, {}), std::invalid_argument);
  CHECK(canvas == RgbImage(47, 40, Rgb32f{}));
  RgbImage taller(48, 41, Rgb32f{});
  CHECK_THROWS_WITH(record_triangle_onto(taller, kTriangle, {}),
                    "record onto a canvas of 48x41 for an input of 48x40");
}
