#pragma once
// Putting generated vertices on the subpixel grid. The exact method's contract is the coverage of
// the vertices snapped to its 1/2^bits grid, while the reference decides on the input as given; a
// vertex off that grid would make the two legitimately differ. So every vertex the generator emits
// is a multiple of 2^-bits, and then snapping is the identity and any difference is a real error.
#include <cmath>
#include <cstdint>

#include "src/vec2.hpp"

namespace scantrace::stress {

// The nearest multiple of 2^-bits (ties away from zero: any tie rule will do here, the point is
// only that the result is on the grid). Exact for |v| * 2^bits < 2^53.
inline double on_grid(double v, int bits) {
  return std::ldexp(std::round(std::ldexp(v, bits)), -bits);
}
inline Vec2 on_grid(Vec2 p, int bits) {
  return {on_grid(p.x, bits), on_grid(p.y, bits)};
}

inline bool is_on_grid(double v, int bits) {
  const double scaled = std::ldexp(v, bits);
  return std::isfinite(scaled) && scaled == std::floor(scaled);
}

// Grid units (multiples of 2^-bits) to pixels: exact.
inline double from_units(std::int64_t u, int bits) {
  return std::ldexp(static_cast<double>(u), -bits);
}
inline std::int64_t to_units(double v, int bits) {
  return static_cast<std::int64_t>(std::ldexp(v, bits));
}

}  // namespace scantrace::stress
