// frame_text::markup_number, the two-decimal numbers of the SVG and canvas JSON backends: its fast
// path (integer rounding of v·100) prints what snprintf("%.2f") prints, trailing zeros dropped, for
// every kind of value: random ones at every scale, exact hundredths and their neighbours, ties
// (where %.2f rounds the exact binary value half to even: 0.125 is "0.12", 0.375 "0.38"), values
// near zero of either sign, and values too large for the fast path.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>

#include "viz/frame_text.hpp"

using scantrace::viz::frame_text::markup_number;
using scantrace::viz::frame_text::number_by_printf;

TEST_CASE("frame_text::markup_number prints what %.2f prints, zeros dropped", "[viz][frame_text]") {
  std::mt19937_64 rng(33);
  std::uniform_real_distribution<double> unit(-1, 1);
  int checked = 0;
  const auto same = [&](double v) {
    INFO("v = " << v);
    REQUIRE(markup_number(v) == number_by_printf(v));
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
  CHECK(markup_number(0.125) == "0.12");  // a tie, by hand: half to even
  CHECK(markup_number(-0.004) == "0");
  CHECK(markup_number(12.5) == "12.5");
  CHECK(checked > 1000000);
}

namespace {

// Values at and around the ties of two decimals, where v·100 rounded does not say how %.2f
// rounds: exact ties (odd multiples of 1/8: 0.125 is 12.5 hundredths) at every scale up to the
// fast path's limit, and the doubles a few steps either side of them and of the nearest doubles to
// the other ties ((n + 0.5) / 100), of either sign.
template <class Check>
void around_ties(Check&& check) {
  std::mt19937_64 rng(133);
  const auto with_neighbours = [&](double v) {
    for (const double x : {v, -v}) {
      double up = x, down = x;
      check(x);
      for (int k = 0; k < 3; ++k) {
        check(up = std::nextafter(up, 1e300));
        check(down = std::nextafter(down, -1e300));
      }
    }
  };
  for (long long k = 0; k < 20000; ++k) with_neighbours((2 * k + 1) / 8.0);
  for (int scale = 0; scale < 24; ++scale)
    for (int i = 0; i < 400; ++i) {
      const auto k = static_cast<long long>(rng() % (std::uint64_t{1} << scale));
      with_neighbours((2 * k + 1) / 8.0);
      with_neighbours((static_cast<double>(k) + 0.5) / 100.0);
    }
  for (const double v : {9999999.875, 9999999.995, 1e7 - 0.125, 4194303.625, 0.005, 1.005, 2.675})
    with_neighbours(v);
}

}  // namespace

TEST_CASE("frame_text::markup_number at and around ties prints what %.2f prints",
          "[viz][frame_text]") {
  int checked = 0;
  around_ties([&](double v) {
    INFO("v = " << v);
    REQUIRE(markup_number(v) == number_by_printf(v));
    ++checked;
  });
  CHECK(markup_number(0.375) == "0.38");  // a tie, by hand: half to even
  CHECK(markup_number(-0.625) == "-0.62");
  CHECK(checked > 500000);
}

TEST_CASE("frame_text::number_value is what a reader of %.2f's digits gets", "[viz][frame_text]") {
  // strtod of snprintf's digits: the reference number_value stands for (the canvas frame's numbers
  // are handed over without their text, viz/frame_json.hpp's to_numbers).
  std::mt19937_64 rng(34);
  std::uniform_real_distribution<double> unit(-1, 1);
  int checked = 0;
  const auto same = [&](double v) {
    INFO("v = " << v);
    const double want = std::strtod(number_by_printf(v).c_str(), nullptr);
    const double got = scantrace::viz::frame_text::number_value(v);
    REQUIRE(got == want);
    REQUIRE(std::signbit(got) == std::signbit(want));
    ++checked;
  };
  for (int i = 0; i < 100000; ++i) same(unit(rng) * std::pow(10.0, (i % 14) - 4));
  around_ties(same);
  for (const double v : {0.0, -0.0, -0.004, 1e7 + 0.125, 1e12 + 0.375, -3e15})
    same(v);
  CHECK(checked > 500000);
}
