#include "edge_table.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace scantrace {

void EdgeTable::build(std::span<const FixedPoint> points, const SubpixelGrid& grid, FillRule rule) {
  edges_.clear();
  horizontal_.clear();
  first_row_ = std::numeric_limits<i64>::max();
  last_row_ = std::numeric_limits<i64>::min();
  const int n = static_cast<int>(points.size());
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
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
    // Half-open in y under the top-left rule: an edge owns the rows whose centre lies in
    // [y_top, y_bottom). A vertex shared by two edges of a chain then belongs to exactly one of
    // them, so the active list always holds exactly two edges per row of a convex polygon.
    e.first_row = grid.ceil_to_pixel(e.p_top.y);
    e.last_row = rule == FillRule::top_left ? grid.ceil_to_pixel(e.p_bottom.y) - 1
                                            : grid.floor_to_pixel(e.p_bottom.y);
    if (e.first_row <= e.last_row) {
      first_row_ = std::min(first_row_, e.first_row);
      last_row_ = std::max(last_row_, e.last_row);
    }
    edges_.push_back(e);
  }
  // Insertion sort: a polygon has few edges, most already in order, and std::sort's set-up costs
  // more than sorting three.
  for (std::size_t i = 1; i < edges_.size(); ++i)
    for (std::size_t j = i; j > 0 && edges_[j].first_row < edges_[j - 1].first_row; --j)
      std::swap(edges_[j], edges_[j - 1]);
  if (first_row_ > last_row_) first_row_ = 0, last_row_ = -1;
}

}  // namespace scantrace
