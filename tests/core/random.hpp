#pragma once
// A small deterministic generator (splitmix64) with its own conversions to doubles and integers,
// so that the random test cases are the same with every standard library (the std distributions
// are implementation-defined).
#include <cstdint>

#include "src/color.hpp"
#include "src/vec2.hpp"

namespace sttest {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

  // Uniform in [0, 1): the top 53 bits as a binary fraction.
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  // Uniform in [lo, hi] (the modulo bias is irrelevant at these range sizes).
  long long integer(long long lo, long long hi) {
    return lo + static_cast<long long>(next() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  bool coin() { return (next() >> 63) != 0; }

  scantrace::Color color() { return {unit(), unit(), unit()}; }
  scantrace::Vec2 point(double x0, double x1, double y0, double y1) {
    return {uniform(x0, x1), uniform(y0, y1)};
  }

 private:
  std::uint64_t state_;
};

}  // namespace sttest
