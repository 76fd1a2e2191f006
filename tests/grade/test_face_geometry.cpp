// FaceGeometry's distance questions against the plain formula written here: the distance to the
// outline is the least std::hypot over the three segments, outline_within(x, y, d) is "that
// distance is at most d", and within(x, y, d) is "that distance is at most d, or the centre is
// inside". The grader decides with squared lengths where they
// settle the question (face_geometry.cpp); these cases hold it to hypot's answers bit for bit,
// on random centres and on centres placed at d pixels from an edge to the last few ulps.
#include <algorithm>
#include <cmath>
#include <random>

#include <catch2/catch.hpp>

#include "grade/face_geometry.hpp"

using scantrace::Color;
using scantrace::Scene;
using scantrace::Vec2;
using scantrace::grade::FaceGeometry;

namespace {

double plain_segment_distance(Vec2 a, Vec2 b, double x, double y) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  const double t = std::clamp(len2 > 0 ? ((x - a.x) * dx + (y - a.y) * dy) / len2 : 0, 0.0, 1.0);
  return std::hypot(a.x + t * dx - x, a.y + t * dy - y);
}

double plain_distance(const FaceGeometry& g, double x, double y) {
  const auto& p = g.snapped();
  return std::min({plain_segment_distance(p[0], p[1], x, y),
                   plain_segment_distance(p[1], p[2], x, y),
                   plain_segment_distance(p[2], p[0], x, y)});
}

bool plain_inside(const FaceGeometry& g, double x, double y) {
  const auto& p = g.snapped();
  const double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
  if (area == 0) return false;
  const double w0 = ((p[1].x - x) * (p[2].y - y) - (p[2].x - x) * (p[1].y - y)) / area;
  const double w1 = ((p[2].x - x) * (p[0].y - y) - (p[0].x - x) * (p[2].y - y)) / area;
  return w0 >= 0 && w1 >= 0 && 1 - w0 - w1 >= 0;
}

Scene one_triangle(Vec2 a, Vec2 b, Vec2 c) {
  Scene s;
  s.width = s.height = 512;
  s.vertices = {a, b, c};
  s.vcolors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  s.depth = {1, 1, 1};
  s.faces = {{0, 1, 2}};
  return s;
}

}  // namespace

TEST_CASE("distance_to_outline, outline_within and within give the answers of hypot at the threshold too") {
  std::mt19937_64 rng(34);
  std::uniform_real_distribution<double> coord(-20, 80), unit(0, 1);
  int near_threshold = 0, checked = 0;
  for (int t = 0; t < 300; ++t) {
    const Scene s =
        one_triangle({coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)});
    const FaceGeometry g(s, 0, 4);
    const auto& p = g.snapped();
    for (int k = 0; k < 200; ++k) {
      double x = 0, y = 0;
      if (k % 2 == 0) {
        x = coord(rng), y = coord(rng);
      } else {
        // A centre at 1.5 pixels (or exactly 1.5 times some ulps off) from an edge, along its
        // normal: where squared lengths and hypot could part.
        const Vec2 a = p[k % 3], b = p[(k + 1) % 3];
        const double u = unit(rng), len = std::hypot(b.x - a.x, b.y - a.y);
        if (len == 0) continue;
        const double off = 1.5 * (1 + static_cast<double>(k % 7 - 3) * 0x1p-52);
        x = a.x + u * (b.x - a.x) + off * (b.y - a.y) / len;
        y = a.y + u * (b.y - a.y) - off * (b.x - a.x) / len;
        near_threshold += std::fabs(plain_distance(g, x, y) - 1.5) < 1e-12;
      }
      const double expected = plain_distance(g, x, y);
      REQUIRE(g.distance_to_outline(x, y) == expected);
      for (double d : {0.0, 1.0, 1.5, expected, std::nextafter(expected, 0.0)}) {
        REQUIRE(g.within(x, y, d) == (expected <= d || plain_inside(g, x, y)));
        REQUIRE(g.outline_within(x, y, d) == (expected <= d));
      }
      ++checked;
    }
  }
  CHECK(checked > 50000);
  CHECK(near_threshold > 1000);  // the threshold cases did occur
}
