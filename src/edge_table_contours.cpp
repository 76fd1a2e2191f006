// The edge table of a polygon of several contours (general polygons, winding_fill.hpp): the same
// edges as EdgeTable::build (add_edge), each contour closed on itself, then a full sort.
#include <algorithm>

#include "edge_table.hpp"

namespace scantrace {

void EdgeTable::build_contours(std::span<const FixedPoint> points,
                               std::span<const int> contour_sizes, const SubpixelGrid& grid,
                               FillRule rule) {
  reset();
  int start = 0;
  for (const int size : contour_sizes) {
    for (int k = 0; k < size; ++k) add_edge(points, start + k, start + (k + 1) % size, grid, rule);
    start += size;
  }
  // A general polygon can have hundreds of edges: a real sort, stable so ties stay in id order.
  std::stable_sort(edges_.begin(), edges_.end(),
                   [](const Edge& a, const Edge& b) { return a.first_row < b.first_row; });
  if (first_row_ > last_row_) first_row_ = 0, last_row_ = -1;
}

}  // namespace scantrace
