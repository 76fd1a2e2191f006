// `why --explain` replays the faces around the pixel as the whole scene draws them: the trace
// holds exactly the faces whose bounding box holds the pixel centre (found here by brute force),
// in the scene's painter's order (a stable sort by mean depth, farthest first, written here), under
// their scene indices, the same faces `why` lists.
#include <algorithm>
#include <numeric>
#include <random>

#include <catch2/catch.hpp>

#include "grade/pixel_story.hpp"
#include "grade/scene_around.hpp"

using namespace scantrace;

TEST_CASE("why --explain's trace names the faces around the pixel by scene index",
          "[grade][why][explain]") {
  std::mt19937 rng(20261123);
  std::uniform_real_distribution<double> coord(0, 80), depth(0, 10);
  Scene s;
  s.width = 80, s.height = 80;
  for (int f = 0; f < 300; ++f) {
    const int base = static_cast<int>(s.vertices.size());
    const double d = std::floor(depth(rng));  // many ties: the order must keep scene order
    for (int k = 0; k < 3; ++k) {
      s.vertices.push_back({coord(rng), coord(rng)});
      s.vcolors.push_back({0.2, 0.4, 0.6});
      s.depth.push_back(d);
    }
    s.faces.push_back({base, base + 1, base + 2});
  }
  FillOptions o;
  for (const auto& [x, y] : {std::pair{40, 40}, std::pair{5, 70}, std::pair{60, 20}}) {
    INFO("pixel (" << x << ", " << y << ")");
    std::vector<int> expected;
    for (int f = 0; f < 300; ++f) {
      double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
      for (int v : s.faces[f]) {
        x0 = std::min(x0, s.vertices[v].x), x1 = std::max(x1, s.vertices[v].x);
        y0 = std::min(y0, s.vertices[v].y), y1 = std::max(y1, s.vertices[v].y);
      }
      if (x >= x0 && x <= x1 && y >= y0 && y <= y1) expected.push_back(f);
    }
    std::stable_sort(expected.begin(), expected.end(), [&](int a, int b) {
      const auto mean = [&](int f) {
        return (s.depth[s.faces[f][0]] + s.depth[s.faces[f][1]] + s.depth[s.faces[f][2]]) / 3;
      };
      return mean(a) > mean(b);
    });
    REQUIRE(expected.size() >= 3);
    const trace::Trace t = grade::trace_around(s, o, x, y, TraceLevel::scanline);
    CHECK(t.triangles() == expected);
    std::vector<int> listed;
    for (const auto& step : grade::why(s, o, x, y).faces) listed.push_back(step.face);
    CHECK(listed == expected);
    // On a coarse grid snapping moves vertices by up to half a pixel: both widen the boxes alike.
    FillOptions coarse;
    coarse.subpixel_bits = 0;
    std::vector<int> coarse_listed;
    for (const auto& step : grade::why(s, coarse, x, y).faces) coarse_listed.push_back(step.face);
    CHECK(grade::trace_around(s, coarse, x, y, TraceLevel::scanline).triangles() == coarse_listed);
    CHECK(coarse_listed.size() > expected.size());
  }
}
