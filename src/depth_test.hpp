#pragma once
// What a depth-testing canvas tells the pixel-level trace about one pixel. A canvas that tests
// depth says so by providing `DepthTest depth_test(int x) const` (the outcome of the last write
// to column x of the current row); the fill asks it only when it narrates pixels, under
// `if constexpr`, so a plain canvas and an untraced fill carry no trace of it.
#include <concepts>

namespace scantrace {

struct DepthTest {
  bool passed = true;
  double depth = 0;   // the triangle's depth at the pixel centre
  double stored = 0;  // what the depth buffer held before the test (+inf: nothing yet)
};

template <class C>
concept DepthTestingCanvas = requires(const C& c, int x) {
  { c.depth_test(x) } -> std::same_as<DepthTest>;
};

}  // namespace scantrace
