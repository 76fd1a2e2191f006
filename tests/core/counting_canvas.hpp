#pragma once
// A canvas that counts how often each pixel is written: a pixel written twice by the triangles of
// a mesh is an overlap, a pixel left at zero inside it a crack. Writes outside the canvas are
// counted separately instead of being performed, so a clipping error is reported, not undefined.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "src/canvas.hpp"

namespace sttest {

class CountingCanvas {
 public:
  CountingCanvas(int width, int height)
      : width_(width), height_(height), counts_(static_cast<std::size_t>(width) * height, 0) {}

  int width() const { return width_; }
  int height() const { return height_; }

  void fill_span(int y, int x_begin, int x_end, scantrace::Color) {
    if (y < 0 || y >= height_ || x_begin < 0 || x_end > width_ || x_begin > x_end) {
      ++out_of_bounds_;
      return;
    }
    for (int x = x_begin; x < x_end; ++x) ++counts_[index(x, y)];
  }
  void set(int x, int y, scantrace::Color) {
    if (x < 0 || x >= width_ || y < 0 || y >= height_) {
      ++out_of_bounds_;
      return;
    }
    ++counts_[index(x, y)];
  }

  int count(int x, int y) const { return counts_[index(x, y)]; }
  long long out_of_bounds() const { return out_of_bounds_; }
  void clear() {
    std::fill(counts_.begin(), counts_.end(), 0);
    out_of_bounds_ = 0;
  }

 private:
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width_ + x; }

  int width_, height_;
  std::vector<int> counts_;
  long long out_of_bounds_ = 0;
};

static_assert(scantrace::Canvas<CountingCanvas>);

}  // namespace sttest
