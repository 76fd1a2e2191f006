#pragma once
// A row-major raster indexed img(x, y) = img[y][x]. The pixel type is a template parameter so that
// the same fill writes the course's float canvas (Rgb32f, colours in [0, 1]) or a coverage-count
// grid in the tests; a pixel type provides `static P from(Color)`.
#include <cassert>
#include <cstddef>
#include <vector>

#include "color.hpp"

namespace scantrace {

// The course's canvas pixel: three floats in [0, 1], RGB order.
struct Rgb32f {
  float r = 0, g = 0, b = 0;
  static Rgb32f from(Color c) {
    return {static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b)};
  }
  Color color() const { return {r, g, b}; }
  friend constexpr bool operator==(Rgb32f, Rgb32f) = default;
};

template <class P>
class Image {
 public:
  using Pixel = P;

  Image() = default;
  Image(int width, int height, P fill = P{})
      : width_(width), height_(height), pixels_(static_cast<std::size_t>(width) * height, fill) {}

  int width() const { return width_; }
  int height() const { return height_; }

  P& operator()(int x, int y) {
    assert(x >= 0 && x < width_ && y >= 0 && y < height_);
    return pixels_[static_cast<std::size_t>(y) * width_ + x];
  }
  const P& operator()(int x, int y) const {
    assert(x >= 0 && x < width_ && y >= 0 && y < height_);
    return pixels_[static_cast<std::size_t>(y) * width_ + x];
  }
  P* row(int y) { return pixels_.data() + static_cast<std::size_t>(y) * width_; }
  const P* row(int y) const { return pixels_.data() + static_cast<std::size_t>(y) * width_; }
  const std::vector<P>& pixels() const { return pixels_; }

  friend bool operator==(const Image&, const Image&) = default;

 private:
  int width_ = 0, height_ = 0;
  std::vector<P> pixels_;
};

using RgbImage = Image<Rgb32f>;

}  // namespace scantrace
