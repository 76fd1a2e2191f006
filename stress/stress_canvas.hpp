#pragma once
// The canvas the stress checks draw into: it counts the writes to each pixel (a pixel written
// twice is an overlap, one left at zero inside a mesh a gap) and keeps the last colour written.
// It remembers the window it was written in, so comparing and clearing cost what was drawn, not
// the whole canvas (16,384 px wide for some families). Writes outside the canvas are counted, not
// performed, so a clipping error is reported instead of corrupting memory.
#include <cstdint>
#include <vector>

#include "src/canvas.hpp"
#include "src/color.hpp"

namespace scantrace::stress {

class StressCanvas {
 public:
  // A cleared canvas of width × height (storage is kept and reused across sizes).
  void reset(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }

  void fill_span(int y, int x_begin, int x_end, Color c);
  void set(int x, int y, Color c);

  int count(int x, int y) const { return counts_[index(x, y)]; }
  Color color(int x, int y) const { return colors_[index(x, y)]; }
  long long out_of_bounds() const { return out_of_bounds_; }

  // The written window [x0, x1) × [y0, y1) (empty when nothing was written).
  bool written() const { return x0_ < x1_; }
  int x0() const { return x0_; }
  int y0() const { return y0_; }
  int x1() const { return x1_; }
  int y1() const { return y1_; }

  // Back to all zero counts, touching only the written window.
  void clear();

 private:
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(x);
  }
  void touch(int x_begin, int x_end, int y);

  int width_ = 0, height_ = 0;
  std::vector<std::uint32_t> counts_;
  std::vector<Color> colors_;
  int x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0;
  long long out_of_bounds_ = 0;
};

static_assert(Canvas<StressCanvas>);

}  // namespace scantrace::stress
