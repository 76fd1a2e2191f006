#include "vector_interp.hpp"

#include <stdexcept>
#include <string>

namespace scantrace {

Color vector_interp(Vec2 p1, Vec2 p2, Color V1, Color V2, double coord, Axis dim) {
  const double a = dim == Axis::x ? p1.x : p1.y;
  const double b = dim == Axis::x ? p2.x : p2.y;
  if (a == b) return (V1 + V2) * 0.5;
  // The two-weight form (1 − t)·V1 + t·V2 reproduces V1 and V2 exactly at the endpoints (t is
  // exactly 0 or 1 there); V1 + t·(V2 − V1) can miss V2 by an ulp.
  const double t = (coord - a) / (b - a);
  return V1 * (1.0 - t) + V2 * t;
}

Color vector_interp(Vec2 p1, Vec2 p2, Color V1, Color V2, double coord, int dim) {
  if (dim != 1 && dim != 2)
    throw std::invalid_argument("vector_interp: dim must be 1 (x) or 2 (y), got " +
                                std::to_string(dim));
  return vector_interp(p1, p2, V1, V2, coord, static_cast<Axis>(dim));
}

}  // namespace scantrace
