#pragma once
// The set-up every fill does before its first row: check the options, snap the vertices to the
// subpixel grid, and reject what cannot fill a pixel of the canvas (docs/design.md §3).
#include <algorithm>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "canvas.hpp"
#include "color.hpp"
#include "fill_options.hpp"
#include "fill_result.hpp"
#include "fixed_point.hpp"
#include "vec2.hpp"

namespace scantrace {

inline void require_valid(const SubpixelGrid& grid) {
  if (!grid.valid())
    throw std::invalid_argument("fill: subpixel_bits must be in 0…" +
                                std::to_string(kMaxSubpixelBits));
}

// Snaps `points` into `snapped`: too_few_vertices or out_of_range when that cannot be done.
inline SkipReason snap_vertices(std::span<const Vec2> points, std::span<const Color> colors,
                                const SubpixelGrid& grid, std::vector<FixedPoint>& snapped) {
  const std::size_t n = points.size();
  if (colors.size() != n) throw std::invalid_argument("fill: one colour per vertex is needed");
  if (n < 3) return SkipReason::too_few_vertices;
  snapped.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!SubpixelGrid::representable(points[i])) return SkipReason::out_of_range;
    snapped[i] = grid.snap(points[i]);
  }
  return SkipReason::none;
}

// The bounding box of snapped vertices in grid units, and the pixel columns and rows whose
// centres it holds under a fill rule, before clipping to the canvas (first > last: none). Computed
// once per polygon: the rejection before set-up and the small-triangle path both read it.
struct GridBox {
  i64 x_min, x_max, y_min, y_max;
  i64 col_first, col_last, row_first, row_last;
};

inline GridBox grid_box(std::span<const FixedPoint> p, const SubpixelGrid& grid, FillRule rule) {
  GridBox b{p[0].x, p[0].x, p[0].y, p[0].y, 0, 0, 0, 0};
  for (const FixedPoint& q : p.subspan(1)) {
    b.x_min = std::min(b.x_min, q.x), b.x_max = std::max(b.x_max, q.x);
    b.y_min = std::min(b.y_min, q.y), b.y_max = std::max(b.y_max, q.y);
  }
  // Under the top-left rule a centre exactly on the box's right or bottom end lies on a right or
  // bottom edge (or is a vertex where one ends), which the rule leaves to the neighbour.
  const bool closed = rule == FillRule::closed;
  b.col_first = grid.ceil_to_pixel(b.x_min), b.row_first = grid.ceil_to_pixel(b.y_min);
  b.col_last = closed ? grid.floor_to_pixel(b.x_max) : grid.ceil_to_pixel(b.x_max) - 1;
  b.row_last = closed ? grid.floor_to_pixel(b.y_max) : grid.ceil_to_pixel(b.y_max) - 1;
  return b;
}

// Whether the bounding box `b` of a polygon holds a pixel centre (no_pixel_centre) and one of the
// canvas's columns [0, width) and rows `band` (offscreen), before any per-row work.
inline SkipReason covers_pixels(const GridBox& b, int width, RowBand band) {
  if (b.col_first > b.col_last || b.row_first > b.row_last) return SkipReason::no_pixel_centre;
  if (b.col_last < 0 || b.col_first >= width || b.row_last < band.begin || b.row_first >= band.end)
    return SkipReason::offscreen;
  return SkipReason::none;
}

}  // namespace scantrace
