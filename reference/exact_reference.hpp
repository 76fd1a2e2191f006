#pragma once
// The exact reference (library code, deliberately independent of the fill): an independent
// brute-force rasterizer. For every pixel centre of the canvas it evaluates the
// polygon's edge functions exactly (128-bit integers on the snapped vertices) and applies the fill
// rule of docs/design.md §3 literally, as a half-plane test with a tie rule. It shares no code with
// the scanline fill in src/ (only the plain Vec2 / Color value types), so agreement between the two
// is evidence rather than a tautology.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "src/color.hpp"
#include "src/fill_options.hpp"
#include "src/vec2.hpp"

namespace scantrace::reference {

// The grid the reference decides on by default: 2^-30 px. Doubles up to ±2^30 px with at most 30
// fractional bits — every input the stress generator makes, every coordinate that a fill method
// snaps to its own grid of 2^-bits — are on it exactly, so the reference decides on the input as
// given. (Products of coordinate differences need up to 2^123: __int128.)
inline constexpr int kExactBits = 30;

using i64 = std::int64_t;
__extension__ using i128 = __int128;

struct GridPt {
  i64 x = 0, y = 0;
};

// The nearest point of the 1/2^bits grid, ties towards +infinity: floor(v + 1/2) evaluated in exact
// arithmetic (the sum v + 1/2 itself is never formed in floating point).
GridPt snap(scantrace::Vec2 p, int bits);
i64 snap(double v, int bits);

// floor(a / b) and ceil(a / b) for b > 0.
i64 floor_div(i64 a, i64 b);
i64 ceil_div(i64 a, i64 b);

// A convex polygon on the grid, decided by half-plane tests.
class Polygon {
 public:
  Polygon(std::span<const scantrace::Vec2> points, int bits);

  bool degenerate() const { return twice_area_ == 0; }
  bool covers(i64 px, i64 py, FillRule rule) const;
  // Barycentric weights of the centre of pixel (px, py); triangles only.
  std::array<double, 3> barycentric(i64 px, i64 py) const;

  // Inclusive pixel range that can hold covered centres (may be empty or off the canvas).
  i64 min_px() const { return ceil_div(min_.x, scale_); }
  i64 max_px() const { return floor_div(max_.x, scale_); }
  i64 min_py() const { return ceil_div(min_.y, scale_); }
  i64 max_py() const { return floor_div(max_.y, scale_); }

 private:
  // Edge function of edge i (vertex i to vertex i + 1) at the grid point (gx, gy), signed so that
  // the interior is positive.
  i128 inside(std::size_t i, i64 gx, i64 gy) const;
  i128 raw_edge(std::size_t i, i64 gx, i64 gy) const;

  i64 scale_;
  std::vector<GridPt> v_;
  std::vector<bool> owns_ties_;  // edge i is a top or a left edge
  i128 twice_area_ = 0;
  int orientation_ = 0;  // sign of twice_area_
  GridPt min_, max_;
};

struct Raster {
  int width = 0, height = 0;
  std::vector<unsigned char> covered;   // covered[y * width + x]
  std::vector<scantrace::Color> color;  // barycentric colour of covered pixels (triangles)
  long long count = 0;

  bool at(int x, int y) const { return covered[static_cast<std::size_t>(y) * width + x] != 0; }
  scantrace::Color color_at(int x, int y) const {
    return color[static_cast<std::size_t>(y) * width + x];
  }
};

// The coverage of a convex polygon on a width × height canvas. When `colors` holds three colours
// (a triangle) the covered pixels also get the exact barycentric interpolation of them at the
// pixel centre, from the snapped vertices.
Raster rasterize(int width, int height, std::span<const scantrace::Vec2> points,
                 std::span<const scantrace::Color> colors, FillRule rule, int bits = kExactBits);

// The coverage of a general polygon (closed contours, vertices one after another; docs/polygons.md)
// under a winding rule, decided per pixel centre without any sweep: the signed crossings of every
// edge with the centre's row (edge rows half-open, y_top <= y < y_bottom) at x_c <= x are summed
// (+1 for an edge going down, -1 up) and the rule applied. When `colors` holds one colour per
// vertex, each covered pixel also gets the Gouraud colour of docs/polygons.md, derived from the
// row's crossings directly: the crossings ordered by (x, slope, vertex id), the inside run holding
// the pixel found by the same winding sums, and its two bounding edges' colours (vertex colours
// interpolated along each edge in y) interpolated linearly in x.
Raster rasterize_contours(int width, int height,
                          std::span<const std::vector<scantrace::Vec2>> contours,
                          std::span<const scantrace::Color> colors, WindingRule rule,
                          int bits = kExactBits);

// The mean of the colours (the flat colour of docs/design.md §2).
scantrace::Color mean_color(std::span<const scantrace::Color> colors);

}  // namespace scantrace::reference
