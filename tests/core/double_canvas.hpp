#pragma once
// A canvas that keeps the colours the fill computes in double: an 8-bit or float image would
// round away a difference in the last bits, which tests of bit-identical results must see. It also
// knows which pixels were written (a colour of -1 never is).
#include <cstddef>
#include <vector>

#include "src/color.hpp"

namespace sttest {

class DoubleCanvas {
 public:
  using Color = scantrace::Color;
  DoubleCanvas(int w, int h)
      : w_(w), h_(h), px_(static_cast<std::size_t>(w) * h, Color{-1, -1, -1}) {}
  int width() const { return w_; }
  int height() const { return h_; }
  void fill_span(int y, int xb, int xe, Color c) {
    for (int x = xb; x < xe; ++x) set(x, y, c);
  }
  void set(int x, int y, Color c) { px_[static_cast<std::size_t>(y) * w_ + x] = c; }
  bool written(int x, int y) const { return px_[static_cast<std::size_t>(y) * w_ + x].r >= 0; }
  friend bool operator==(const DoubleCanvas&, const DoubleCanvas&) = default;

 private:
  int w_, h_;
  std::vector<Color> px_;
};

}  // namespace sttest
