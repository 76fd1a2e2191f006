// Snapping to the subpixel grid and the exact pixel rounding built on it, against independent
// integer arithmetic (the reference's own snapping, reference_raster.cpp).
#include <array>
#include <catch2/catch.hpp>
#include <cmath>

#include "random.hpp"
#include "raster_compare.hpp"
#include "reference_raster.hpp"
#include "src/fixed_point.hpp"
#include "src/scanline_fill.hpp"

using scantrace::SubpixelGrid;
using scantrace::Vec2;
using sttest::i64;

TEST_CASE("snapping rounds to the nearest grid point, ties upward", "[fixed]") {
  const SubpixelGrid g(8);
  // Ties: half a grid unit goes up on both sides of zero (so snapping commutes with translation).
  CHECK(g.snap({0.5 / 256, -0.5 / 256}) == scantrace::FixedPoint{1, 0});
  CHECK(g.snap({1.5 / 256, -1.5 / 256}) == scantrace::FixedPoint{2, -1});
  CHECK(g.snap({3.0, -3.0}) == scantrace::FixedPoint{768, -768});
  CHECK(g.snap({0.3 / 256, 0.7 / 256}) == scantrace::FixedPoint{0, 1});
  CHECK(g.snap({-0.3 / 256, -0.7 / 256}) == scantrace::FixedPoint{0, -1});
  CHECK(SubpixelGrid(0).snap({2.5, -2.5}) == scantrace::FixedPoint{3, -2});
  CHECK(SubpixelGrid(12).snap({1073741824.0, -1073741824.0}) ==
        scantrace::FixedPoint{i64{1} << 42, -(i64{1} << 42)});
}

TEST_CASE("snapping agrees with exact rounding on random coordinates", "[fixed]") {
  sttest::Rng rng(0x2001);
  for (int i = 0; i < 5000; ++i) {
    const int bits = static_cast<int>(rng.integer(0, scantrace::kMaxSubpixelBits));
    const double scale = std::array{1.0, 10.0, 1000.0, 1e6, 1e9}[rng.integer(0, 4)];
    // Half the values are ties or near-ties of the grid: k / 2^(bits+1).
    const double v = rng.coin()
                         ? rng.uniform(-scale, scale)
                         : std::ldexp(static_cast<double>(rng.integer(-4000, 4000)), -bits - 1);
    CAPTURE(bits, v);
    CHECK(SubpixelGrid(bits).snap({v, -v}).x == sttest::ref_snap(v, bits));
    CHECK(SubpixelGrid(bits).snap({v, -v}).y == sttest::ref_snap(-v, bits));
  }
}

// floor(v + 1/2) of the largest double below one half is 0, but evaluated in floating point the sum
// v + 0.5 rounds up to 1.0 (it needs one bit more than a double has), and the point snaps one
// grid unit off: the one input in range where `std::floor(v + 0.5)` is not the nearest grid point.
TEST_CASE("snapping the largest double below a half-unit tie", "[fixed]") {
  const double below_half = std::nextafter(0.5, 0.0);  // 0.49999999999999994
  CHECK(sttest::ref_snap(below_half, 0) == 0);
  CHECK(SubpixelGrid(0).snap({below_half, 0}).x == 0);
  CHECK(SubpixelGrid(8).snap({below_half / 256, 0}).x == 0);
  // Its effect on pixels: the left edge should run through the centres of column 0 (included by
  // the top-left rule); snapped a unit to the right it misses them.
  const std::array<Vec2, 3> t{Vec2{below_half / 256, 0}, Vec2{below_half / 256, 4}, Vec2{4, 4}};
  const std::array<scantrace::Color, 3> c{};
  scantrace::RgbImage img(8, 8, sttest::kSentinel);
  scantrace::fill_triangle(img, t, c, {scantrace::Shading::flat, scantrace::FillRule::top_left});
  CHECK(!(img(0, 2) == sttest::kSentinel));
}

TEST_CASE("pixel rounding of grid coordinates is exact for negative values", "[fixed]") {
  sttest::Rng rng(0x2002);
  for (int i = 0; i < 5000; ++i) {
    const int bits = static_cast<int>(rng.integer(0, scantrace::kMaxSubpixelBits));
    const i64 v = rng.integer(-(i64{1} << 43), i64{1} << 43);
    const i64 near_multiple = rng.integer(-1000, 1000) * (i64{1} << bits) + rng.integer(-2, 2);
    for (const i64 u : {v, near_multiple}) {
      CAPTURE(bits, u);
      CHECK(SubpixelGrid(bits).ceil_to_pixel(u) == sttest::ceil_div(u, i64{1} << bits));
      CHECK(SubpixelGrid(bits).floor_to_pixel(u) == sttest::floor_div(u, i64{1} << bits));
    }
  }
}
