// Painter's order (docs/design.md §2: mean depth, farthest first, stable on ties), the render of an
// overlapping pair, and scene validation naming the offending element.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "random.hpp"
#include "src/painter.hpp"
#include "src/scene.hpp"

namespace {

using scantrace::Color;
using scantrace::Rgb32f;
using scantrace::Scene;
using scantrace::Vec2;

constexpr Color kRed{1, 0, 0}, kBlue{0, 0, 1}, kWhite{1, 1, 1};

// Face 0, red, near: (2,2),(9,2),(2,9), vertex depths 0, 1, 2 (mean 1).
// Face 1, blue, far: (0,0),(8,0),(0,8), vertex depths 9, 10, 11 (mean 10).
// Listed nearest first, so only sorting can put red on top.
Scene overlapping_pair() {
  Scene s;
  s.width = 10;
  s.height = 10;
  s.vertices = {{0, 0}, {8, 0}, {0, 8}, {2, 2}, {9, 2}, {2, 9}};
  s.vcolors = {kBlue, kBlue, kBlue, kRed, kRed, kRed};
  s.depth = {9, 10, 11, 0, 1, 2};
  s.faces = {{3, 4, 5}, {0, 1, 2}};
  return s;
}

bool is(Rgb32f p, Color c) {
  return std::fabs(p.r - c.r) < 1e-6 && std::fabs(p.g - c.g) < 1e-6 && std::fabs(p.b - c.b) < 1e-6;
}

}  // namespace

TEST_CASE("face depth is the mean of the vertex depths", "[painter]") {
  Scene s = overlapping_pair();
  CHECK(scantrace::face_depths(s) == std::vector<double>{1.0, 10.0});
  s.depth = {1, 2, 4, 0, 0, 0};
  s.faces = {{0, 1, 2}, {3, 4, 0}};
  CHECK(scantrace::face_depths(s) == std::vector<double>{7.0 / 3.0, 1.0 / 3.0});
}

TEST_CASE("painter's order: farthest first, ties in face order", "[painter]") {
  CHECK(scantrace::painter_order({1.0, 10.0}) == std::vector<int>{1, 0});
  CHECK(scantrace::painter_order({5, 7, 5, 7, 3}) == std::vector<int>{1, 3, 0, 2, 4});
  CHECK(scantrace::painter_order({2, 2, 2, 2}) == std::vector<int>{0, 1, 2, 3});
  CHECK(scantrace::painter_order({-1, 0.5, -3, 0.5}) == std::vector<int>{1, 3, 0, 2});
  CHECK(scantrace::painter_order({}).empty());
  // Many ties among many faces: a stable sort, not one that happens to be stable on small input.
  std::vector<double> d;
  for (int i = 0; i < 1000; ++i) d.push_back(i % 3);
  const std::vector<int> order = scantrace::painter_order(d);
  REQUIRE(order.size() == 1000);
  for (std::size_t k = 1; k < order.size(); ++k) {
    const bool ok = d[order[k - 1]] > d[order[k]] ||
                    (d[order[k - 1]] == d[order[k]] && order[k - 1] < order[k]);
    if (!ok) FAIL_CHECK("faces " << order[k - 1] << " and " << order[k] << " out of order");
  }
}

// Hand-computed coverage (top-left rule): blue owns x + y <= 7, red owns x, y >= 2 with
// x + y <= 10. Where both do (x, y >= 2 with x + y <= 7: 10 pixels), the nearer red is drawn
// last and wins; near to far it is drawn first, and blue's 10 pixels there are clipped away.
TEST_CASE("render: the nearer triangle wins where they overlap", "[painter]") {
  using scantrace::Occlusion;
  for (const scantrace::Shading shading : {scantrace::Shading::flat, scantrace::Shading::gouraud})
    for (const Occlusion occlusion : {Occlusion::far_to_near, Occlusion::near_to_far}) {
      INFO(scantrace::to_string(occlusion));
      scantrace::RenderStats stats;
      const scantrace::RgbImage img = scantrace::render(
          overlapping_pair(),
          {.shading = shading, .fill_rule = scantrace::FillRule::top_left, .occlusion = occlusion},
          &stats);
      REQUIRE(img.width() == 10);
      REQUIRE(img.height() == 10);
      CHECK(is(img(3, 3), kRed));    // both
      CHECK(is(img(5, 2), kRed));    // both: red's top edge is inclusive
      CHECK(is(img(2, 5), kRed));    // both: red's left edge is inclusive
      CHECK(is(img(2, 6), kRed));    // red only: blue's diagonal (a right edge) excludes it
      CHECK(is(img(0, 0), kBlue));   // blue only
      CHECK(is(img(1, 6), kBlue));   // blue only
      CHECK(is(img(7, 0), kBlue));   // blue only
      CHECK(is(img(8, 0), kWhite));  // on blue's right vertex: excluded
      CHECK(is(img(5, 6), kWhite));  // on red's diagonal (a right edge)
      CHECK(is(img(9, 9), kWhite));
      int red = 0, blue = 0, white = 0;
      for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 10; ++x) {
          const bool in_blue = x + y <= 7, in_red = x >= 2 && y >= 2 && x + y <= 10;
          red += in_red && is(img(x, y), kRed);
          blue += in_blue && !in_red && is(img(x, y), kBlue);
          white += !in_blue && !in_red && is(img(x, y), kWhite);
        }
      CHECK(red + blue + white == 100);
      CHECK(stats.triangles_filled == 2);
      CHECK(stats.triangles_skipped == 0);
      CHECK(stats.path == occlusion);
      if (occlusion == Occlusion::far_to_near) {
        CHECK(stats.pixels == 36 + 28);
      } else {
        CHECK(stats.pixels == 36 + 28 - 10);
        CHECK(stats.pixels_clipped == 10);
        CHECK(stats.triangles_hidden == 0);
      }
    }
}

TEST_CASE("render: swapping the depths swaps the winner", "[painter]") {
  Scene s = overlapping_pair();
  s.depth = {0, 1, 2, 9, 10, 11};
  const scantrace::RgbImage img = scantrace::render(s);
  CHECK(is(img(3, 3), kBlue));
  CHECK(is(img(2, 6), kRed));
}

TEST_CASE("render: equal depths draw in face order", "[painter]") {
  Scene s = overlapping_pair();
  s.depth = {5, 5, 5, 5, 5, 5};
  CHECK(is(scantrace::render(s)(3, 3), kBlue));  // face 1 (blue) is drawn last
  s.faces = {{0, 1, 2}, {3, 4, 5}};
  CHECK(is(scantrace::render(s)(3, 3), kRed));
}

TEST_CASE("validate accepts a good scene and names the first bad element", "[scene]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto element = [](const Scene& s) {
    const auto problem = scantrace::validate(s);
    return problem ? problem->element : std::string("(none)");
  };
  CHECK(element(overlapping_pair()) == "(none)");

  Scene s = overlapping_pair();
  s.faces = {{3, 4, 5}, {0, 6, 2}};  // 6 vertices: index 6 is one past the end
  CHECK(element(s) == "faces[1]");
  s.faces = {{-1, 4, 5}, {0, 1, 2}};
  CHECK(element(s) == "faces[0]");

  s = overlapping_pair();
  s.vcolors.pop_back();
  CHECK(element(s) == "vcolors");
  s = overlapping_pair();
  s.depth.push_back(1);
  CHECK(element(s) == "depth");

  s = overlapping_pair();
  s.vertices[2].y = nan;
  CHECK(element(s) == "vertices[2]");
  s = overlapping_pair();
  s.vertices[5].x = std::numeric_limits<double>::infinity();
  CHECK(element(s) == "vertices[5]");
  s = overlapping_pair();
  s.depth[3] = nan;
  CHECK(element(s) == "depth[3]");

  s = overlapping_pair();
  s.vcolors[4] = {0.5, 1.0000001, 0};
  CHECK(element(s) == "vcolors[4]");
  s = overlapping_pair();
  s.vcolors[0] = {-0.01, 0, 0};
  CHECK(element(s) == "vcolors[0]");
  s = overlapping_pair();
  s.vcolors[1] = {0, nan, 0};
  CHECK(element(s) == "vcolors[1]");
  s = overlapping_pair();
  s.background = {1.5, 1, 1};
  CHECK(element(s) == "background");

  s = overlapping_pair();
  s.width = 0;
  CHECK(element(s) == "width/height");
  s = overlapping_pair();
  s.height = -3;
  CHECK(element(s) == "width/height");
  s = overlapping_pair();
  s.width = s.height = 65536;  // 2^32 pixels
  CHECK(element(s) == "width/height");
  // Colour components exactly 0 and 1 are in range.
  s = overlapping_pair();
  s.vcolors[0] = {0, 1, 0};
  CHECK(element(s) == "(none)");
}

TEST_CASE("painter_order equals a stable sort on awkward depths", "[painter]") {
  // Independent check of the radix sort: std::stable_sort with the comparison the course states.
  sttest::Rng rng(0x7001);
  std::vector<int> order;
  scantrace::PainterSortBuffers buffers;
  const double specials[] = {0.0,
                             -0.0,
                             1e-310,
                             -1e-310,
                             1e300,
                             -1e300,
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             12923.6328125,
                             0.5};
  // Depths that differ by less than a float's precision: the sort's float keys are equal for
  // them, and only the doubles can order them (a sort on the floats alone fails these rounds).
  const double close[] = {1.0,           1.0 + 0x1p-40, 1.0 - 0x1p-41,  1.0 + 0x1p-30, 3.5,
                          3.5 + 0x1p-38, -2.0,          -2.0 - 0x1p-39, 1e300,         1e301,
                          -1e300,        1e-40,         1e-45};
  for (int round = 0; round < 400; ++round) {
    std::vector<double> d(static_cast<std::size_t>(rng.integer(0, 400)));
    const bool collide = round % 2 == 1;
    for (double& v : d)
      v = collide      ? close[rng.integer(0, 12)]
          : rng.coin() ? specials[rng.integer(0, 9)]
                       : std::ldexp(rng.uniform(-1, 1), static_cast<int>(rng.integer(-60, 60)));
    std::vector<int> expected(d.size());
    std::iota(expected.begin(), expected.end(), 0);
    std::stable_sort(expected.begin(), expected.end(), [&](int a, int b) { return d[a] > d[b]; });
    CHECK(scantrace::painter_order(d) == expected);
    // The same sort into buffers kept from the previous rounds (of other sizes and keys): what a
    // render with a kept RenderScratch does. Stale keys or counts would show here.
    scantrace::painter_order(d, order, buffers);
    CHECK(order == expected);
  }
}
