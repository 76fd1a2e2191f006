#pragma once
// The stress generator's random numbers: splitmix64 (src/splitmix64.hpp) and exact laws. The std
// distributions are implementation-defined, and libm's exp/log/sin/cos are not required to round
// the same way everywhere, so nothing here uses them: only integer arithmetic, exact power-of-two
// scaling and sqrt (correctly rounded by IEEE 754). A seed therefore names the same triangles on
// every platform, which is what makes a printed reproducer replayable.
#include <cmath>
#include <cstdint>

#include "src/splitmix64.hpp"

namespace scantrace::stress {

class Rng : public SplitMix64 {
 public:
  using SplitMix64::SplitMix64;

  // True with probability num/den.
  bool chance(int num, int den) { return integer(0, den - 1) < num; }

  // Spread evenly over the binary orders of magnitude of [lo, hi] (0 < lo < hi): an exponent,
  // then a mantissa, both uniform — a log-uniform law made of exact operations only.
  double scale(double lo, double hi) {
    const int e_lo = std::ilogb(lo), e_hi = std::ilogb(hi);
    for (;;) {
      const double v =
          std::ldexp(1.0 + unit(), static_cast<int>(integer(e_lo, e_hi)));  // [2^e, 2^(e+1))
      if (v >= lo && v <= hi) return v;
    }
  }

  // A unit vector in a uniformly random direction (rejection from the square, no trigonometry).
  void direction(double& dx, double& dy) {
    for (;;) {
      const double x = uniform(-1, 1), y = uniform(-1, 1), r2 = x * x + y * y;
      if (r2 > 0.01 && r2 <= 1) {
        const double r = std::sqrt(r2);
        dx = x / r;
        dy = y / r;
        return;
      }
    }
  }
};

// The generator of case `index` of family number `family` under `seed`: every case has its own
// stream, so a case can be regenerated alone from (family, seed, index).
inline Rng case_rng(std::uint64_t seed, int family, std::uint64_t index) {
  Rng mix(seed ^ (0xd1b54a32d192ed03ULL * (static_cast<std::uint64_t>(family) + 1)));
  Rng scrambled(mix.next() ^ (index * 0xbf58476d1ce4e5b9ULL));
  // One more round of mixing so that consecutive indices start far apart in the sequence.
  return Rng(scrambled.next());
}

}  // namespace scantrace::stress
