#pragma once
// The active edge list of the scanline sweep: the edges that cross the current row, each with its
// stepper (edge_stepper.hpp) holding where it crosses that row, kept in left-to-right order.
//
// An edge enters on its first row (edges come from the edge table in the order of that row) and
// retires after its last one. Between two such events the list does not change, so the sweep
// moves through runs of rows (next_event_row); within a run only the steppers advance.
#include <algorithm>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "color.hpp"
#include "edge.hpp"
#include "edge_table.hpp"

namespace scantrace {

// An edge in the active list: its geometry and where the stepper has it on the current row.
template <class Stepper>
struct ActiveEdge {
  Edge edge;
  Stepper at;
};

// Order of two active edges on the current row: by x, then (where they meet) by slope, so that
// two edges leaving a common top vertex are ordered as they are just below it.
template <class Stepper>
bool before_on_row(const ActiveEdge<Stepper>& a, const ActiveEdge<Stepper>& b) {
  const auto by_x = a.at <=> b.at;
  if (by_x != 0) return by_x < 0;
  return compare_slopes(a.edge, b.edge) < 0;
}

// before_on_row, then the edge id: a total order, so a list sorted by it does not depend on the
// order its edges entered in (edges that cross one another between rows swap places).
template <class Stepper>
bool ordered_on_row(const ActiveEdge<Stepper>& a, const ActiveEdge<Stepper>& b) {
  if (before_on_row(a, b)) return true;
  if (before_on_row(b, a)) return false;
  return a.edge.id < b.edge.id;
}

template <class Stepper>
class ActiveEdgeList {
 public:
  using value_type = ActiveEdge<Stepper>;

  // Starts a sweep over `table` (its storage is kept: nothing is allocated once it has grown).
  void reset(const EdgeTable& table) {
    edges_ = &table.edges();
    next_ = 0;
    active_.clear();
  }

  // Removes the edges whose last row is before `y`, keeping the others in order; `retired(edge)`
  // is told of each.
  template <class OnRetire>
  void retire(i64 y, OnRetire&& retired) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < active_.size(); ++i) {
      if (active_[i].edge.last_row >= y) {
        if (kept != i) active_[kept] = active_[i];
        ++kept;
      } else {
        retired(active_[i].edge);
      }
    }
    active_.resize(kept);
  }

  // Lets the edges whose first row is at or before `y` enter, each started at row `y` and put in
  // its place in x order (an insertion step: a list holds a few edges). An edge that crosses no
  // row up to here (it lies above the canvas, or between two rows) is passed over unstepped;
  // `entered(edge)` is told of the others.
  template <class OnEnter>
  void enter(i64 y, const SubpixelGrid& grid, std::span<const Color> colors, OnEnter&& entered) {
    const std::vector<Edge>& edges = *edges_;
    for (; next_ < edges.size() && edges[next_].first_row <= y; ++next_) {
      if (edges[next_].last_row < y) continue;
      active_.push_back({edges[next_], {}});
      active_.back().at.start(edges[next_], y, grid, colors);
      for (std::size_t k = active_.size() - 1; k > 0 && before_on_row(active_[k], active_[k - 1]);
           --k)
        std::swap(active_[k], active_[k - 1]);
      entered(edges[next_]);
    }
  }

  // The last row, at most `y_last`, before which no edge enters or retires: rows y … that one
  // are a run over which the list only steps.
  i64 run_last(i64 y_last) const {
    const std::vector<Edge>& edges = *edges_;
    i64 last = next_ < edges.size() ? edges[next_].first_row - 1 : y_last;
    for (const value_type& a : active_) last = std::min(last, a.edge.last_row);
    return std::min(last, y_last);
  }

  // Holds just the two edges `left` and `right`, in that order, already started at the current
  // row: the triangle sweep (fast/triangle_sweep.hpp) knows which of its edges is on which side without
  // comparing crossings, and has no edge table to take them from.
  void hold(const Edge& left, const Stepper& l, const Edge& right, const Stepper& r) {
    edges_ = nullptr;
    next_ = 0;
    active_.resize(2);
    active_[0] = {left, l};
    active_[1] = {right, r};
  }

  // Restores x order after edges crossed one another (general polygons). The list is nearly
  // sorted, so an insertion sort is linear in practice.
  void sort_by_x() {
    for (std::size_t i = 1; i < active_.size(); ++i)
      for (std::size_t j = i; j > 0 && ordered_on_row(active_[j], active_[j - 1]); --j)
        std::swap(active_[j], active_[j - 1]);
  }

  // Every edge to the next row.
  void advance() {
    for (value_type& a : active_) a.at.advance();
  }

  std::size_t size() const { return active_.size(); }
  value_type& operator[](std::size_t i) { return active_[i]; }
  const value_type& operator[](std::size_t i) const { return active_[i]; }
  value_type& front() { return active_.front(); }
  value_type& back() { return active_.back(); }
  auto begin() const { return active_.begin(); }
  auto end() const { return active_.end(); }

 private:
  const std::vector<Edge>* edges_ = nullptr;
  std::size_t next_ = 0;  // the first edge of the table that has not entered yet
  std::vector<value_type> active_;
};

}  // namespace scantrace
