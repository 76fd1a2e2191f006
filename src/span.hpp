#pragma once
// A span: the pixels of one row between two active edges that the fill rule puts inside the
// polygon. The pixel centres x_begin … x_end − 1 (half-open, clipped to the canvas) are those the
// edges' exact crossings x_left and x_right enclose (docs/design.md §3: [ceil(x_left),
// ceil(x_right))). A convex polygon has at most one span a row; a general polygon one per inside
// interval.
#include "color.hpp"
#include "fixed_point.hpp"

namespace scantrace {

struct Span {
  int left_edge = 0, right_edge = 0;  // the active edges bounding it (edge ids)
  double x_left = 0, x_right = 0;     // their exact crossings of the row (rounded for display)
  i64 x_begin = 0, x_end = 0;         // its pixels, half-open, clipped to the canvas
  bool has_colors = false;            // Gouraud: the colours of its end pixels are known
  Color begin, end;                   // colours of pixels x_begin and x_end - 1

  bool empty() const { return x_begin >= x_end; }
  i64 size() const { return x_end - x_begin; }
  // Where pixel x lies between the crossings: 0 at x_left, 1 at x_right (0 for a point span).
  double weight(int x) const { return x_right > x_left ? (x - x_left) / (x_right - x_left) : 0.0; }
};

}  // namespace scantrace
