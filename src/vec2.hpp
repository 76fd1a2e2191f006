#pragma once
// A point of the image plane in pixel units: x is the column (grows right), y the row (grows
// down); pixel (x, y) is centred on the integer point (x, y) (docs/design.md §2).

namespace scantrace {

struct Vec2 {
  double x = 0, y = 0;
  friend constexpr bool operator==(Vec2, Vec2) = default;
};

}  // namespace scantrace
