#include "edge_table.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace scantrace {

void EdgeTable::reset() {
  edges_.clear();
  horizontal_.clear();
  first_row_ = std::numeric_limits<i64>::max();
  last_row_ = std::numeric_limits<i64>::min();
}

void EdgeTable::add_edge(std::span<const FixedPoint> points, int i, int j, const SubpixelGrid& grid,
                         FillRule rule) {
  const FixedPoint a = points[i], b = points[j];
  if (a.y == b.y) {
    horizontal_.push_back({i, i, j, a.y});
    return;
  }
  const Edge& e = edges_.emplace_back(edge_between(points.data(), i, j, i, grid, rule));
  if (e.first_row <= e.last_row) {
    first_row_ = std::min(first_row_, e.first_row);
    last_row_ = std::max(last_row_, e.last_row);
  }
}

void EdgeTable::build(std::span<const FixedPoint> points, const SubpixelGrid& grid, FillRule rule) {
  reset();
  const int n = static_cast<int>(points.size());
  for (int i = 0; i < n; ++i) add_edge(points, i, i + 1 == n ? 0 : i + 1, grid, rule);
  const std::size_t count = edges_.size();
  // Sorted by (first_row, id). Edges are listed in id order, so a stable sort by first_row is
  // enough; for a triangle, three compare-and-swap steps. Which way each goes depends on the
  // triangle, i.e. is unpredictable, so they select rather than branch (the swap is of whole
  // edges, but a triangle's edge table is only three of them).
  const auto order = [](Edge& a, Edge& b) {
    const bool swap = b.first_row < a.first_row;
    const Edge lo = swap ? b : a, hi = swap ? a : b;
    a = lo, b = hi;
  };
  if (count == 3) {
    order(edges_[1], edges_[2]);
    order(edges_[0], edges_[1]);
    order(edges_[1], edges_[2]);
  } else if (count == 2) {
    order(edges_[0], edges_[1]);
  } else if (count > 3) {
    std::stable_sort(edges_.begin(), edges_.end(),
                     [](const Edge& a, const Edge& b) { return a.first_row < b.first_row; });
  }
  if (first_row_ > last_row_) first_row_ = 0, last_row_ = -1;
}

}  // namespace scantrace
