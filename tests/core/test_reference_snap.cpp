// reference::snap against floor(v·2^k + 1/2) computed in integers from the double's own bits, for
// every magnitude up to 2^30 px on the reference's default grid (2^-30), where v·2^k reaches 2^60
// and a floating-point "+ 0.5" is no longer exact; and the triangle through a far vertex on which
// the inexact snap made the reference disagree with a correct fill.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>

#include "reference/exact_reference.hpp"
#include "src/scanline_fill.hpp"

namespace {

using scantrace::reference::i128;
using scantrace::reference::i64;

// v = m·2^e with m an integer (53 bits); v·2^k + 1/2 = (2m·2^(e+k) + 1) / 2, floored with an
// arithmetic shift (which floors negative values too). No floating-point rounding anywhere.
i64 exact_round_half_up(double v, int k) {
  if (v == 0) return 0;
  int e = 0;
  const double frac = std::frexp(v, &e);                 // v = frac·2^e
  const i64 m = static_cast<i64>(std::ldexp(frac, 53));  // exact, |m| < 2^53
  const int shift = e - 53 + k;                          // v·2^k = m·2^shift
  if (shift >= 0) return static_cast<i64>(static_cast<i128>(m) << shift);
  const i128 twice = (static_cast<i128>(m) << 1) + (i128{1} << -shift);  // 2·(v·2^k + 1/2)·2^-shift
  return static_cast<i64>(twice >> (1 - shift));
}

TEST_CASE("reference::snap is floor(v*2^k + 1/2) exactly for |v| up to 2^30", "[reference]") {
  const int k = scantrace::reference::kExactBits;
  // The cases the old "f + 0.5" got wrong: |v·2^k| ≥ 2^52, i.e. |v| ≥ 2^22 px on the 2^-30 grid.
  for (double v : {4194304.0, 4194305.0, 1e9, -1e9, 1e9 - 23, 23 - 1e9, 1073741823.0, 4194304.5,
                   -4194304.5, 12345678.25, std::ldexp(1.0, 30)}) {
    INFO("v = " << v);
    CHECK(scantrace::reference::snap(v, k) == exact_round_half_up(v, k));
  }
  std::mt19937_64 rng(20);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> magnitude(-10, 30);
  for (int i = 0; i < 200000; ++i) {
    const double v = std::ldexp(unit(rng), magnitude(rng));
    for (int bits : {0, 8, 16, k}) {
      INFO("v = " << v << ", bits " << bits);
      REQUIRE(scantrace::reference::snap(v, bits) == exact_round_half_up(v, bits));
    }
  }
  // Exact ties: half a grid unit rounds up, in both signs.
  CHECK(scantrace::reference::snap(std::ldexp(3.0, -31), k) == 2);    // 1.5 units
  CHECK(scantrace::reference::snap(-std::ldexp(3.0, -31), k) == -1);  // -1.5 units
}

TEST_CASE("the reference agrees with the fill on a tie through a far vertex", "[reference]") {
  // The diagonal from (0, 23) to (1e9, 23 - 1e9) runs through pixel centres (x, 23 - x): ties
  // decided by the top-left rule, which both must decide alike.
  const std::array<scantrace::Vec2, 3> v{{{0, 23}, {1e9, 23 - 1e9}, {0, -1e9}}};
  const std::array<scantrace::Color, 3> c{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  const int w = 24, h = 24;
  scantrace::RgbImage img(w, h, scantrace::Rgb32f::from({1, 1, 1}));
  scantrace::FillOptions opt;
  opt.shading = scantrace::Shading::flat;
  scantrace::fill_triangle(img, v, c, opt);
  const auto ref = scantrace::reference::rasterize(w, h, v, {}, scantrace::FillRule::top_left);
  // By hand: on the canvas the triangle is bounded by its left edge x = 0 (ties owned by the
  // top-left rule) and the diagonal x + y = 23, with the interior on its left: a right edge, whose
  // ties are not owned. The third edge runs near y = -1e9. So a pixel is covered iff x + y < 23.
  int disagreements = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool filled = !(img(x, y) == scantrace::Rgb32f::from({1, 1, 1}));
      const bool expected = x + y < 23;
      disagreements += (filled != ref.at(x, y)) + (ref.at(x, y) != expected);
    }
  CHECK(disagreements == 0);
}

}  // namespace
