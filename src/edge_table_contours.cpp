// The edge table of a polygon of several contours (general polygons, winding_fill.hpp). Kept
// apart from EdgeTable::build, the convex fill's hot set-up path, which is tuned for triangles.
#include <algorithm>
#include <limits>

#include "edge_table.hpp"

namespace scantrace {

void EdgeTable::build_contours(std::span<const FixedPoint> points,
                               std::span<const int> contour_sizes, const SubpixelGrid& grid,
                               FillRule rule) {
  edges_.clear();
  horizontal_.clear();
  first_row_ = std::numeric_limits<i64>::max();
  last_row_ = std::numeric_limits<i64>::min();
  int start = 0;
  for (const int size : contour_sizes) {
    for (int k = 0; k < size; ++k) {
      const int i = start + k, j = start + (k + 1) % size;
      const FixedPoint a = points[i], b = points[j];
      if (a.y == b.y) {
        horizontal_.push_back({i, i, j, a.y});
        continue;
      }
      Edge e;
      e.id = i;
      e.top = a.y < b.y ? i : j;
      e.bottom = a.y < b.y ? j : i;
      e.p_top = points[e.top];
      e.p_bottom = points[e.bottom];
      // Half-open rows, as for triangles: with the edges of every contour owning [y_top,
      // y_bottom), a vertex where a contour turns is counted once and one where it passes
      // through (an edge going down, the next going down too) once as well.
      e.first_row = grid.ceil_to_pixel(e.p_top.y);
      e.last_row = rule == FillRule::top_left ? grid.ceil_to_pixel(e.p_bottom.y) - 1
                                              : grid.floor_to_pixel(e.p_bottom.y);
      if (e.first_row <= e.last_row) {
        first_row_ = std::min(first_row_, e.first_row);
        last_row_ = std::max(last_row_, e.last_row);
      }
      edges_.push_back(e);
    }
    start += size;
  }
  // A general polygon can have hundreds of edges: a real sort, stable so ties stay in id order.
  std::stable_sort(edges_.begin(), edges_.end(),
                   [](const Edge& a, const Edge& b) { return a.first_row < b.first_row; });
  if (first_row_ > last_row_) first_row_ = 0, last_row_ = -1;
}

}  // namespace scantrace
