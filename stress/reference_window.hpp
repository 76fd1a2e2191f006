#pragma once
// The exact reference (src/exact_reference.hpp) evaluated over the only part of the canvas where
// it can cover anything: the polygon's bounding box clipped to the canvas. Every pixel centre in
// that window is tested by brute force, as the reference does; only the storage is compact (a
// convex polygon meets a row in one run of pixels, so a row is stored as its run, with the exact
// barycentric colour of each pixel of the run for triangles).
#include <cstdint>
#include <span>
#include <vector>

#include "src/color.hpp"
#include "src/fill_options.hpp"
#include "src/vec2.hpp"

namespace scantrace::stress {

class ReferenceWindow {
 public:
  ReferenceWindow() = default;
  // `colors`: one per vertex of a triangle for the colours, or empty for coverage only.
  ReferenceWindow(int width, int height, std::span<const Vec2> points,
                  std::span<const Color> colors, FillRule rule);

  // The window [x0, x1) × [y0, y1); empty when the polygon covers no centre of the canvas.
  int x0() const { return x0_; }
  int y0() const { return y0_; }
  int x1() const { return x1_; }
  int y1() const { return y1_; }

  bool covers(int x, int y) const {
    if (y < y0_ || y >= y1_) return false;
    const Run& r = runs_[static_cast<std::size_t>(y - y0_)];
    return x >= r.begin && x < r.end;
  }
  // The exact barycentric colour of a covered pixel (triangles with colours only).
  Color color(int x, int y) const {
    const Run& r = runs_[static_cast<std::size_t>(y - y0_)];
    return colors_[static_cast<std::size_t>(r.first_color + (x - r.begin))];
  }
  long long count() const { return count_; }

 private:
  struct Run {
    int begin = 0, end = 0;  // covered pixels [begin, end) of the row
    long long first_color = 0;
  };
  int x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0;
  std::vector<Run> runs_;
  std::vector<Color> colors_;
  long long count_ = 0;
};

}  // namespace scantrace::stress
