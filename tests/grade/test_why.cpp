// `why` on pixels chosen for what they test; every statement is checked against the exact
// reference (coverage, exact edge intersections) and the test's own painter's order.
#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>

#include "grade/pixel_story.hpp"
#include "src/painter.hpp"
#include "wrong_renderers.hpp"

using namespace gradetest;
using scantrace::grade::Outcome;
using scantrace::grade::PixelStory;
using scantrace::grade::why;

namespace {

Scene small_scene() {
  Scene s;
  s.width = 120, s.height = 100;
  const auto add = [&](Vec2 a, Vec2 b, Vec2 c, double depth, Color col) {
    const int base = static_cast<int>(s.vertices.size());
    for (const Vec2 v : {a, b, c}) {
      s.vertices.push_back(v);
      s.vcolors.push_back(col);
      s.depth.push_back(depth);
    }
    s.vcolors[base + 1] = {col.b, col.r, col.g};  // Gouraud has something to interpolate
    s.faces.push_back({base, base + 1, base + 2});
  };
  // 0, 1: a square split along its diagonal x + y = 14 (integer vertices).
  add({2, 2}, {12, 2}, {2, 12}, 50, {1, 0, 0});
  add({12, 2}, {12, 12}, {2, 12}, 50, {0, 1, 0});
  // 2-6: five nested triangles around (60, 50), nearer and nearer.
  for (int k = 0; k < 5; ++k)
    add({30.5 + 3 * k, 20.25 + 2 * k}, {95.75 - 3 * k, 35.5 + k}, {55.125, 90.5 - 3 * k}, 40 - k,
        {0.1 + 0.15 * k, 0.5, 0.9 - 0.1 * k});
  // 7: zero area.
  add({20, 60}, {30, 70}, {40, 80}, 1, {0, 0, 0});
  return s;
}

// The exact intersection of the face's edges with row y: (x_L, x_R), or nothing.
std::optional<std::pair<double, double>> exact_row(const std::vector<Vec2>& v, int y) {
  double lo = 1e300, hi = -1e300;
  bool any = false;
  for (int i = 0; i < 3; ++i) {
    const Vec2 a = v[i], b = v[(i + 1) % 3];
    if (a.y == b.y || y < std::min(a.y, b.y) || y > std::max(a.y, b.y)) continue;
    const double x = a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y);
    lo = std::min(lo, x), hi = std::max(hi, x), any = true;
  }
  if (!any) return std::nullopt;
  return std::pair{lo, hi};
}

// Checks every statement of the story of (x, y).
void check_story(const Scene& s, const FillOptions& o, int x, int y) {
  INFO("pixel (" << x << ", " << y << ")");
  const PixelStory story = why(s, o, x, y);
  // The faces: those whose bounding box holds the centre, in the test's painter's order.
  std::vector<int> expected_faces;
  for (int f : order(s, false)) {
    const auto p = points(s, f);
    if (x >= std::min({p[0].x, p[1].x, p[2].x}) && x <= std::max({p[0].x, p[1].x, p[2].x}) &&
        y >= std::min({p[0].y, p[1].y, p[2].y}) && y <= std::max({p[0].y, p[1].y, p[2].y}))
      expected_faces.push_back(f);
  }
  if (o.visibility == Visibility::zbuffer) std::sort(expected_faces.begin(), expected_faces.end());
  std::vector<int> got_faces;
  for (const auto& f : story.faces) got_faces.push_back(f.face);
  CHECK(got_faces == expected_faces);

  std::optional<int> last_writer;
  for (const auto& f : story.faces) {
    INFO("face " << f.face << ": " << scantrace::grade::to_string(f.outcome));
    const reference::Polygon poly(points(s, f.face), o.subpixel_bits);
    const bool covered = poly.covers(x, y, o.fill_rule);
    if (poly.degenerate()) {
      CHECK(f.outcome == Outcome::skipped);
      CHECK(f.skip_reason == "degenerate");
      continue;
    }
    CHECK((f.outcome == Outcome::written || f.outcome == Outcome::depth_rejected) == covered);
    if (f.outcome != Outcome::row_outside) {
      const auto row = exact_row(f.vertices, y);
      REQUIRE(row);
      REQUIRE(f.active_points.size() >= 2);
      CHECK(f.active_points.front().x == Approx(row->first).margin(1e-9));
      CHECK(f.active_points.back().x == Approx(row->second).margin(1e-9));
      if (!f.span) {  // the row crosses the face but no pixel centre lies in it
        CHECK(std::ceil(row->first) >= std::ceil(row->second));
        continue;
      }
      CHECK(f.span->x_begin ==
            std::max<long long>(0, static_cast<long long>(std::ceil(row->first))));
      if (o.fill_rule == FillRule::top_left)
        CHECK(f.span->x_end == static_cast<long long>(std::ceil(row->second)));
      CHECK((f.outcome == Outcome::left_of_span) == (x < f.span->x_begin));
    }
    if (f.outcome == Outcome::written) last_writer = f.face;
    if (f.outcome == Outcome::written && o.shading == Shading::gouraud) {
      const auto w = poly.barycentric(x, y);
      const auto c = colours(s, f.face);
      const Color exact = c[0] * w[0] + c[1] * w[1] + c[2] * w[2];
      CHECK(f.color->r == Approx(exact.r).margin(1e-4));
      CHECK(f.color->b == Approx(exact.b).margin(1e-4));
    }
  }
  CHECK(story.final_face == last_writer);
  const Rgb32f rendered = render<Rgb32f>(s, o)(x, y);
  CHECK(static_cast<float>(story.final_color.r) == rendered.r);
  CHECK(static_cast<float>(story.final_color.g) == rendered.g);
  CHECK(static_cast<float>(story.final_color.b) == rendered.b);
  CHECK_FALSE(story.to_text().empty());
}

}  // namespace

TEST_CASE("why: a pixel on a shared edge names the owner and the face that does not get it",
          "[grade][why]") {
  const Scene s = small_scene();
  FillOptions o;
  check_story(s, o, 7, 7);
  const PixelStory story = why(s, o, 7, 7);
  REQUIRE(story.faces.size() == 2);
  CHECK(story.faces[0].outline == "edge");
  CHECK(story.faces[1].outline == "edge");
  // Exactly one of the two faces gets it under the top-left rule, both under the closed rule.
  const auto gets = [](const auto& f) { return f.outcome == Outcome::written; };
  CHECK(std::count_if(story.faces.begin(), story.faces.end(), gets) == 1);
  REQUIRE(story.notes.size() == 2);
  CHECK(story.notes[0].find("on the other side") != std::string::npos);
  o.fill_rule = FillRule::closed;
  const PixelStory closed = why(s, o, 7, 7);
  CHECK(std::count_if(closed.faces.begin(), closed.faces.end(), gets) == 2);
  check_story(s, o, 7, 7);
}

TEST_CASE("why: a vertex, a horizontal top edge, five faces, nothing", "[grade][why]") {
  const Scene s = small_scene();
  for (Shading sh : {Shading::flat, Shading::gouraud}) {
    FillOptions o;
    o.shading = sh;
    check_story(s, o, 12, 2);    // the vertex shared by both halves of the square
    check_story(s, o, 5, 2);     // on the square's horizontal top edge: owned (a top edge)
    check_story(s, o, 5, 12);    // on its bottom edge: not owned
    check_story(s, o, 60, 50);   // inside five nested faces
    check_story(s, o, 110, 95);  // outside every face
    check_story(s, o, 30, 70);   // on the zero-area face
  }
  FillOptions o;
  const PixelStory five = why(s, o, 60, 50);
  CHECK(std::count_if(five.faces.begin(), five.faces.end(),
                      [](const auto& f) { return f.outcome == Outcome::written; }) == 5);
  CHECK(five.final_face == 6);
  const PixelStory top = why(s, o, 5, 2);  // both halves' boxes hold it; the upper one owns it
  REQUIRE(top.faces.size() == 2);
  CHECK(top.faces[0].face == 0);
  CHECK(top.faces[0].outcome == Outcome::written);
  CHECK(top.faces[0].outline == "edge");
  CHECK(top.faces[1].outcome != Outcome::written);
  CHECK(top.final_face == 0);
  const PixelStory none = why(s, o, 110, 95);
  CHECK(none.faces.empty());
  CHECK_FALSE(none.final_face);
  const PixelStory degenerate = why(s, o, 30, 70);
  REQUIRE(degenerate.faces.size() == 1);
  CHECK(degenerate.faces[0].outcome == Outcome::skipped);
  CHECK_THROWS_AS(why(s, o, 120, 5), std::out_of_range);
}

TEST_CASE("why: under a z-buffer, the depth test rejecting a write", "[grade][why]") {
  Scene s = small_scene();
  // Face order through the depth buffer: the nested faces come nearer and nearer, so reverse
  // them to make later faces farther: their writes are rejected.
  for (double& d : s.depth) d = -d;
  FillOptions o;
  o.visibility = Visibility::zbuffer;
  check_story(s, o, 60, 50);
  const PixelStory story = why(s, o, 60, 50);
  int rejected = 0;
  for (const auto& f : story.faces)
    if (f.outcome == Outcome::depth_rejected) {
      ++rejected;
      REQUIRE(f.depth_test);
      REQUIRE(f.depth_test->stored);
      CHECK(f.depth_test->depth > *f.depth_test->stored);
    }
  CHECK(rejected == 4);
  CHECK(story.final_face == 2);
}
