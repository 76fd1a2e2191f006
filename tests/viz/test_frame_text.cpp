// frame_text::number, the two-decimal numbers of the SVG and canvas JSON backends: its fast path
// (integer rounding of v·100) prints what snprintf("%.2f") prints, trailing zeros dropped, for
// every kind of value: random ones at every scale, exact hundredths and their neighbours, ties
// (where %.2f rounds the exact binary value half to even: 0.125 is "0.12", 0.375 "0.38"), values
// near zero of either sign, and values too large for the fast path.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "viz/frame_text.hpp"

using scantrace::viz::frame_text::number;
using scantrace::viz::frame_text::number_by_printf;

TEST_CASE("frame_text::number prints what %.2f prints, zeros dropped", "[viz][frame_text]") {
  std::mt19937_64 rng(33);
  std::uniform_real_distribution<double> unit(-1, 1);
  int checked = 0;
  const auto same = [&](double v) {
    INFO("v = " << v);
    REQUIRE(number(v) == number_by_printf(v));
    ++checked;
  };
  for (int i = 0; i < 200000; ++i) same(unit(rng) * std::pow(10.0, (i % 14) - 4));
  for (int n = -100000; n <= 100000; ++n) {
    const double v = n / 100.0;
    same(v);
    same(std::nextafter(v, 1e300));
    same(std::nextafter(v, -1e300));
    same((n + 0.5) / 100.0);  // ties, or the doubles nearest them
  }
  for (double v : {0.125, 0.375, -0.125, 2.675, 1.005, 0.005, -0.005, 0.0, -0.0, -0.004, 1e7 + 0.125,
                   123456789.125, 1e12 + 0.375, -3e15, 1e300})
    same(v);
  CHECK(number(0.125) == "0.12");  // a tie, by hand: half to even
  CHECK(number(-0.004) == "0");
  CHECK(number(12.5) == "12.5");
  CHECK(checked > 1000000);
}
