#pragma once
// A coarse view of a depth buffer for rejecting hidden faces before their set-up (hierarchical
// z, one level): per tile of 8 × 8 pixels, how many of its pixels no face has written yet and an
// upper bound of the depths written there. When every pixel of every tile a face's box touches
// has been written, and the face's depth is farther than each tile's bound at every point of the
// box, no pixel of the face can pass the depth test, and the face need not be set up at all.
//
// The bound is the largest depth ever written into the tile, not the largest stored now: a pixel
// written again is written nearer, so the old bound still holds, and keeping it costs one max per
// write where an exact maximum would rescan the tile. Drawing near to far (src/painter.hpp's
// render_zbuffer_near_to_far) makes the first depth written to a pixel nearly always its last, so
// the bound is tight where it matters.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace scantrace {

class DepthTiles {
 public:
  static constexpr int kShift = 3;  // tiles of 8 × 8 pixels
  static constexpr int kSize = 1 << kShift;

  // Every pixel of a width × height image unwritten, keeping the storage.
  void reset(int width, int height) {
    width_ = width, height_ = height;
    tiles_x_ = (width + kSize - 1) >> kShift;
    const int tiles_y = (height + kSize - 1) >> kShift;
    tiles_.assign(static_cast<std::size_t>(tiles_x_) * tiles_y, Tile{});
    for (int ty = 0; ty < tiles_y; ++ty)
      for (int tx = 0; tx < tiles_x_; ++tx) {
        const int w = std::min(kSize, width - (tx << kShift)),
                  h = std::min(kSize, height - (ty << kShift));
        tiles_[static_cast<std::size_t>(ty) * tiles_x_ + tx].unwritten = w * h;
      }
  }

  // Pixel (x, y), which held `before` (+infinity when unwritten), now holds `depth`.
  void wrote(int x, int y, double before, double depth) {
    Tile& t = tiles_[static_cast<std::size_t>(y >> kShift) * tiles_x_ + (x >> kShift)];
    if (before == std::numeric_limits<double>::infinity()) --t.unwritten;
    t.bound = std::max(t.bound, depth);
  }

  // Whether every pixel of columns [x0, x1] and rows [y0, y1] (clipped to the image) has been
  // written, with depths below `nearest`: a face whose depth is at least `nearest` everywhere in
  // that box would lose every depth test there. False for a box off the image.
  bool all_nearer(int x0, int y0, int x1, int y1, double nearest) const {
    x0 = std::max(x0, 0), y0 = std::max(y0, 0);
    x1 = std::min(x1, width_ - 1), y1 = std::min(y1, height_ - 1);
    if (x0 > x1 || y0 > y1) return false;
    for (int ty = y0 >> kShift; ty <= y1 >> kShift; ++ty) {
      const Tile* row = tiles_.data() + static_cast<std::size_t>(ty) * tiles_x_;
      for (int tx = x0 >> kShift; tx <= x1 >> kShift; ++tx)
        if (row[tx].unwritten != 0 || !(row[tx].bound < nearest)) return false;
    }
    return true;
  }

 private:
  struct Tile {
    int unwritten = 0;
    double bound = -std::numeric_limits<double>::infinity();
  };
  int width_ = 0, height_ = 0, tiles_x_ = 0;
  std::vector<Tile> tiles_;
};

}  // namespace scantrace
