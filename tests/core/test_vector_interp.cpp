// The course's vector_interp: hand-computed values (dyadic fractions, so exact in binary), its
// endpoints, extrapolation, the degenerate midpoint rule and argument checking.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "random.hpp"
#include "src/vector_interp.hpp"

using scantrace::Axis;
using scantrace::Color;
using scantrace::Vec2;
using scantrace::vector_interp;

namespace {

bool near(Color a, Color b, double tol) {
  return std::fabs(a.r - b.r) <= tol && std::fabs(a.g - b.g) <= tol && std::fabs(a.b - b.b) <= tol;
}

}  // namespace

namespace Catch {
template <>
struct StringMaker<Color> {
  static std::string convert(Color c) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g)", c.r, c.g, c.b);
    return buf;
  }
};
}  // namespace Catch

TEST_CASE("vector_interp along x and along y", "[vector_interp]") {
  const Vec2 p1{0, 0}, p2{10, 20};
  const Color v1{0, 0, 0}, v2{1, 0.5, 0.25};
  // x = 2.5 is a quarter of the way from 0 to 10; y = 5 a quarter of the way from 0 to 20.
  CHECK(vector_interp(p1, p2, v1, v2, 2.5, 1) == Color{0.25, 0.125, 0.0625});
  CHECK(vector_interp(p1, p2, v1, v2, 5.0, 2) == Color{0.25, 0.125, 0.0625});
  CHECK(vector_interp(p1, p2, v1, v2, 5.0, Axis::x) == Color{0.5, 0.25, 0.125});
  CHECK(vector_interp(p1, p2, v1, v2, 15.0, Axis::y) == Color{0.75, 0.375, 0.1875});
  // Only the chosen coordinate matters: the same segment read along y at 10 is halfway.
  CHECK(vector_interp({3, 10}, {7, 30}, Color{0.5, 1, 0}, Color{1, 0, 0.5}, 20.0, 2) ==
        Color{0.75, 0.5, 0.25});
  // Decreasing coordinate along the segment: from x = 8 down to x = 0, x = 6 is a quarter.
  CHECK(vector_interp({8, 1}, {0, 2}, Color{1, 1, 1}, Color{0, 0, 0}, 6.0, 1) ==
        Color{0.75, 0.75, 0.75});
}

// At p2, t = (b - a) / (b - a) is exactly 1, but V1 + (V2 - V1) · 1 is two roundings and can miss
// V2 by an ulp (0.2 + (0.9 - 0.2) is 0.8999999999999999). A Gouraud vertex colour should be
// reproduced exactly at its vertex.
TEST_CASE("vector_interp returns the endpoint values at the endpoints", "[vector_interp]") {
  const Color v1{0.2, 0.4, 0.6}, v2{0.9, 0.1, 0.3};
  CHECK(vector_interp({1, 2}, {5, 11}, v1, v2, 1.0, 1) == v1);
  CHECK(vector_interp({1, 2}, {5, 11}, v1, v2, 5.0, 1) == v2);
  CHECK(vector_interp({1, 2}, {5, 11}, v1, v2, 2.0, 2) == v1);
  CHECK(vector_interp({1, 2}, {5, 11}, v1, v2, 11.0, 2) == v2);
  // Random colours and segments, V1 often much smaller than V2.
  sttest::Rng rng(0x5001);
  int mismatches = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec2 a = rng.point(-100, 100, -100, 100), b = rng.point(-100, 100, -100, 100);
    const Color c1 = rng.color() * rng.unit(), c2 = rng.color();
    for (const int dim : {1, 2}) {
      const double at_a = dim == 1 ? a.x : a.y, at_b = dim == 1 ? b.x : b.y;
      const bool exact = vector_interp(a, b, c1, c2, at_a, dim) == c1 &&
                         vector_interp(a, b, c1, c2, at_b, dim) == c2;
      if (!exact && mismatches++ == 0) {  // report the first one only
        CAPTURE(a.x, a.y, b.x, b.y, c1, c2, dim);
        CHECK(vector_interp(a, b, c1, c2, at_a, dim) == c1);
        CHECK(vector_interp(a, b, c1, c2, at_b, dim) == c2);
      }
    }
  }
  CHECK(mismatches == 0);
}

TEST_CASE("vector_interp extrapolates outside the segment", "[vector_interp]") {
  const Vec2 p1{0, 0}, p2{10, 20};
  const Color v1{0, 0, 0}, v2{1, 0.5, 0.25};
  CHECK(vector_interp(p1, p2, v1, v2, -5.0, 1) == Color{-0.5, -0.25, -0.125});
  CHECK(vector_interp(p1, p2, v1, v2, 20.0, 1) == Color{2, 1, 0.5});
  CHECK(vector_interp(p1, p2, v1, v2, -10.0, 2) == Color{-0.5, -0.25, -0.125});
  CHECK(vector_interp(p1, p2, v1, v2, 30.0, 2) == Color{1.5, 0.75, 0.375});
}

TEST_CASE("vector_interp on a degenerate axis returns the midpoint value", "[vector_interp]") {
  const Color v1{0.25, 1, 0}, v2{0.75, 0, 0.5}, mid{0.5, 0.5, 0.25};
  CHECK(vector_interp({3, 4}, {3, 4}, v1, v2, 3.0, 1) == mid);  // p1 == p2
  CHECK(vector_interp({3, 4}, {3, 4}, v1, v2, 4.0, 2) == mid);
  CHECK(vector_interp({3, 4}, {3, 9}, v1, v2, 3.0, 1) == mid);  // vertical segment, along x
  CHECK(vector_interp({3, 4}, {3, 9}, v1, v2, 100.0, 1) == mid);
  CHECK(vector_interp({3, 4}, {8, 4}, v1, v2, 4.0, 2) == mid);  // horizontal segment, along y
  // Along the other axis the same segments are ordinary.
  CHECK(vector_interp({3, 4}, {3, 8}, v1, v2, 5.0, 2) == Color{0.375, 0.75, 0.125});
}

TEST_CASE("vector_interp is symmetric in its endpoints", "[vector_interp]") {
  sttest::Rng rng(0x5002);
  for (int i = 0; i < 2000; ++i) {
    const Vec2 a = rng.point(-50, 50, -50, 50), b = rng.point(-50, 50, -50, 50);
    const Color c1 = rng.color(), c2 = rng.color();
    const double x = rng.uniform(-60, 60), y = rng.uniform(-60, 60);
    CAPTURE(a.x, a.y, b.x, b.y, x, y);
    // Two roundings in different orders: equal up to a few ulps relative to the extrapolation.
    CHECK(near(vector_interp(a, b, c1, c2, x, 1), vector_interp(b, a, c2, c1, x, 1), 1e-9));
    CHECK(near(vector_interp(a, b, c1, c2, y, 2), vector_interp(b, a, c2, c1, y, 2), 1e-9));
    // The degenerate rule is exactly symmetric.
    CHECK(vector_interp(a, a, c1, c2, x, 1) == vector_interp(a, a, c2, c1, x, 1));
  }
}

TEST_CASE("vector_interp rejects a dim other than 1 or 2", "[vector_interp]") {
  const Vec2 p1{0, 0}, p2{1, 1};
  const Color v{0.5, 0.5, 0.5};
  CHECK_THROWS_AS(vector_interp(p1, p2, v, v, 0.5, 0), std::invalid_argument);
  CHECK_THROWS_AS(vector_interp(p1, p2, v, v, 0.5, 3), std::invalid_argument);
  CHECK_THROWS_AS(vector_interp(p1, p2, v, v, 0.5, -1), std::invalid_argument);
  CHECK_NOTHROW(vector_interp(p1, p2, v, v, 0.5, 1));
  CHECK_NOTHROW(vector_interp(p1, p2, v, v, 0.5, 2));
}
