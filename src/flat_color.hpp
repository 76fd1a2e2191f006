#pragma once
// The flat colour of a polygon: the mean of its vertex colours. One function for every fill, so a
// triangle filled as a triangle, as a convex polygon or as a general polygon gets the same bits.
#include <algorithm>
#include <span>
#include <vector>

#include "color.hpp"
#include "fixed_point.hpp"

namespace scantrace {

namespace detail {

// flat_color of a polygon of more than three vertices: its colours summed in the order of the
// vertices sorted by (y, x, index). Out of line: a triangle never needs it.
[[gnu::noinline]] inline Color flat_color_sorted(std::span<const FixedPoint> p,
                                                 std::span<const Color> colors,
                                                 std::vector<int>& order) {
  // Insertion sort by (y, x, index): polygons are small, and std::sort's set-up costs more.
  const auto before = [&](int a, int b) {
    return p[a].y != p[b].y ? p[a].y < p[b].y : p[a].x != p[b].x ? p[a].x < p[b].x : a < b;
  };
  order.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::size_t j = i;
    for (; j > 0 && before(static_cast<int>(i), order[j - 1]); --j) order[j] = order[j - 1];
    order[j] = static_cast<int>(i);
  }
  Color sum;
  for (int i : order) sum += colors[i];
  return sum * (1.0 / static_cast<double>(p.size()));
}

}  // namespace detail

// The mean of `colors`, summed in a canonical order of the (snapped) vertices `p`, so that listing
// the same polygon's vertices in another order cannot change the last bit of the result. `order`
// is working storage. Inline for a triangle, whose faces are most of every scene: the call would
// cost more than the sum.
inline Color flat_color(std::span<const FixedPoint> p, std::span<const Color> colors,
                        std::vector<int>& order) {
  if (p.size() != 3) return detail::flat_color_sorted(p, colors, order);
  // A triangle: each channel's three values are summed smallest first, which is as canonical as
  // a vertex order and takes six min/max instructions instead of a sort whose branches the
  // processor cannot predict.
  const auto sum3 = [](double a, double b, double c) {
    const double lo = std::min(a, b), hi = std::max(a, b);
    return (std::min(lo, c) + std::max(lo, std::min(hi, c))) + std::max(hi, c);
  };
  return Color{sum3(colors[0].r, colors[1].r, colors[2].r),
               sum3(colors[0].g, colors[1].g, colors[2].g),
               sum3(colors[0].b, colors[1].b, colors[2].b)} *
         (1.0 / 3.0);
}

}  // namespace scantrace
