#include "stress/stress_canvas.hpp"

#include <algorithm>

namespace scantrace::stress {

void StressCanvas::reset(int width, int height) {
  clear();
  width_ = width;
  height_ = height;
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  // Counts are all zero after clear(), in any layout, so growing only appends zeros.
  if (counts_.size() < n) {
    counts_.resize(n, 0);
    colors_.resize(n);
  }
}

void StressCanvas::touch(int x_begin, int x_end, int y) {
  if (!written()) {
    x0_ = x_begin, x1_ = x_end, y0_ = y, y1_ = y + 1;
    return;
  }
  x0_ = std::min(x0_, x_begin), x1_ = std::max(x1_, x_end);
  y0_ = std::min(y0_, y), y1_ = std::max(y1_, y + 1);
}

void StressCanvas::fill_span(int y, int x_begin, int x_end, Color c) {
  if (x_begin >= x_end) return;
  if (y < 0 || y >= height_ || x_begin < 0 || x_end > width_) {
    out_of_bounds_ += static_cast<long long>(x_end) - x_begin;
    return;
  }
  touch(x_begin, x_end, y);
  for (int x = x_begin; x < x_end; ++x) {
    ++counts_[index(x, y)];
    colors_[index(x, y)] = c;
  }
}

void StressCanvas::set(int x, int y, Color c) {
  if (x < 0 || x >= width_ || y < 0 || y >= height_) {
    ++out_of_bounds_;
    return;
  }
  touch(x, x + 1, y);
  ++counts_[index(x, y)];
  colors_[index(x, y)] = c;
}

void StressCanvas::clear() {
  for (int y = y0_; y < y1_; ++y)
    std::fill(counts_.begin() + static_cast<std::ptrdiff_t>(index(x0_, y)),
              counts_.begin() + static_cast<std::ptrdiff_t>(index(x1_, y)), 0u);
  x0_ = x1_ = y0_ = y1_ = 0;
  out_of_bounds_ = 0;
}

}  // namespace scantrace::stress
