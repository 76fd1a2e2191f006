#pragma once
#include "color.hpp"
#include "vec2.hpp"

namespace scantrace {

enum class Axis { x = 1, y = 2 };

// The course's `vector_interp(p1, p2, V1, V2, coord, dim)`: the value at the point of segment
// p1–p2 whose coordinate on `dim` (1 = x, 2 = y) is `coord`, by linear interpolation of V1 (at p1)
// and V2 (at p2). Outside the segment the line is extended (linear extrapolation).
//
// Degenerate cases: when p1 and p2 have the same coordinate on `dim` (including p1 == p2) the
// position along the segment is undefined; the result is then the midpoint value (V1 + V2) / 2,
// chosen because it is symmetric in the endpoints, so swapping them never changes a pixel.
Color vector_interp(Vec2 p1, Vec2 p2, Color V1, Color V2, double coord, Axis dim);

// The same interpolation with the course's integer `dim` (1 or 2); any other value throws
// std::invalid_argument.
Color vector_interp(Vec2 p1, Vec2 p2, Color V1, Color V2, double coord, int dim);

}  // namespace scantrace
