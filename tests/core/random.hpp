#pragma once
// The tests' random numbers: the library's splitmix64 (the same cases with every standard library)
// plus colours and points.
#include <cstdint>

#include "src/color.hpp"
#include "src/splitmix64.hpp"
#include "src/vec2.hpp"

namespace sttest {

class Rng : public scantrace::SplitMix64 {
 public:
  using SplitMix64::SplitMix64;

  scantrace::Color color() { return {unit(), unit(), unit()}; }
  scantrace::Vec2 point(double x0, double x1, double y0, double y1) {
    return {uniform(x0, x1), uniform(y0, y1)};
  }
};

}  // namespace sttest
