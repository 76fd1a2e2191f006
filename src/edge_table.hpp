#pragma once
// The edge table of one polygon: its non-horizontal edges, sorted by the first scanline they
// cross, with the scanline range each is active on; horizontal edges are kept aside because they
// never cross a scanline (their only effect, which pixels on their own row belong to the polygon,
// follows from the fill rule applied to the neighbouring edges).
#include <span>
#include <vector>

#include "edge.hpp"
#include "fill_options.hpp"

namespace scantrace {

struct HorizontalEdge {
  int id = 0;
  int from = 0, to = 0;  // vertex indices
  i64 y = 0;             // grid units
};

class EdgeTable {
 public:
  // Rebuilds the table for the polygon `points` (grid units); reuses its storage, so a renderer
  // that keeps one EdgeTable allocates nothing per triangle once it has warmed up.
  void build(std::span<const FixedPoint> points, const SubpixelGrid& grid, FillRule rule);
  // The same for a polygon of several closed contours stored one after another in `points`
  // (`contour_sizes` vertices each). Edge ids stay global vertex indices: edge i runs from vertex
  // i to the next vertex of its contour, the first vertex of the contour for the last one.
  void build_contours(std::span<const FixedPoint> points, std::span<const int> contour_sizes,
                      const SubpixelGrid& grid, FillRule rule);

  const std::vector<Edge>& edges() const { return edges_; }  // sorted by (first_row, id)
  const std::vector<HorizontalEdge>& horizontal() const { return horizontal_; }
  i64 first_row() const { return first_row_; }  // rows the polygon covers (first > last: none)
  i64 last_row() const { return last_row_; }

 private:
  void reset();
  // Edge i → j of `points` into the table (or among the horizontal edges), widening the rows.
  void add_edge(std::span<const FixedPoint> points, int i, int j, const SubpixelGrid& grid,
                FillRule rule);

  std::vector<Edge> edges_;
  std::vector<HorizontalEdge> horizontal_;
  i64 first_row_ = 0, last_row_ = -1;
};

}  // namespace scantrace
