// The small-triangle spans (src/small_triangle.hpp): the half-space test in 32-bit SIMD lanes must
// give every row exactly the pixels the exact reference covers, with every Highway target's
// kernel this CPU can run, on every grid the fill supports — including boxes whose edge functions
// come close to the 32-bit limit, where a set-up that let a larger triangle in would wrap around.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "random.hpp"
#include "reference_raster.hpp"
#include "src/fill_setup.hpp"
#include "src/small_triangle.hpp"

using namespace scantrace;

namespace {

constexpr int W = 56, H = 56;

// A triangle in a box of up to `size` pixels somewhere around the canvas (partly off it at times),
// its vertices on whole and half pixels in one case of two: centres on edges and vertices.
std::array<Vec2, 3> random_triangle(sttest::Rng& rng, double size) {
  const Vec2 corner = rng.point(-10, W + 2, -10, H + 2);
  std::array<Vec2, 3> v;
  const bool coarse = rng.next() % 2 == 0;
  for (Vec2& p : v) {
    p = {corner.x + rng.uniform(0, size), corner.y + rng.uniform(0, 4 * size)};
    if (coarse) p = {std::round(p.x * 2) / 2, std::round(p.y * 2) / 2};
  }
  if (rng.next() % 6 == 0) v[1].y = v[0].y;  // a flat top or bottom
  return v;
}

}  // namespace

TEST_CASE("small triangles: every row's span is the exact reference's, on every SIMD target",
          "[core][simd][small_triangle]") {
  const auto kernels = small_triangle_kernels();
  REQUIRE(!kernels.empty());
#if defined(__x86_64__)
  CHECK(kernels.size() >= 2);  // SSSE3 or better, and the portable kernel
#endif
  for (const auto& kernel : kernels) {
    INFO("Highway target " << kernel.target);
    sttest::Rng rng(20261125);
    int taken = 0, declined = 0, near_limit = 0;
    long long pixels = 0;
    for (int i = 0; i < 16000; ++i) {
      const int bits = std::array{0, 4, 8, 12}[i % 4];
      // Sizes from slivers to boxes the set-up must refuse (wider than 32 columns, or too large
      // for 32 bits on the finest grid).
      const double size = std::array{0.7, 3.0, 9.0, 24.0, 40.0}[(i / 4) % 5];
      const std::array<Vec2, 3> v = random_triangle(rng, size);
      const SubpixelGrid grid(bits);
      const std::array<FixedPoint, 3> p{grid.snap(v[0]), grid.snap(v[1]), grid.snap(v[2])};
      const i64 cross =
          (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
      if (cross == 0) continue;
      const int a = static_cast<int>(rng.next() % (H + 1)),
                b = static_cast<int>(rng.next() % (H + 1));
      const RowBand band = i % 3 == 0 ? RowBand{0, H} : RowBand{std::min(a, b), std::max(a, b)};
      const GridBox box = grid_box(p, grid, FillRule::top_left);
      SmallTriangle t;
      if (!small_triangle(p, box, cross > 0, grid, W, band, t)) {
        ++declined;
        continue;
      }
      ++taken;
      // How close the lanes' edge functions may come to 2^31 (the set-up's own bound).
      const i64 dx = box.x_max - box.x_min, dy = box.y_max - box.y_min, s = grid.scale();
      if (dy * (dx + 2 * kSmallTriangleLanes * s) + dx * (dy + 2 * s) > (i64{1} << 29))
        ++near_limit;

      const sttest::RefRaster ref =
          sttest::ref_rasterize(W, H, v, std::array<Color, 3>{Color{}, Color{}, Color{}},
                                sttest::RefRule::top_left, bits);
      std::vector<RowSpan> spans(static_cast<std::size_t>(t.rows) + 1, RowSpan{-7, -7});
      kernel.function(t, spans.data());
      REQUIRE(spans.back().begin == -7);  // nothing written past the box's rows
      for (int y = band.begin; y < band.end; ++y) {
        int first = W, last = -1, count = 0;
        for (int x = 0; x < W; ++x)
          if (ref.at(x, y)) first = std::min(first, x), last = std::max(last, x), ++count;
        const bool in_box = y >= t.row0 && y < t.row0 + t.rows;
        INFO("triangle " << i << " (" << v[0].x << "," << v[0].y << ") (" << v[1].x << "," << v[1].y
                         << ") (" << v[2].x << "," << v[2].y << "), grid bits " << bits << ", row "
                         << y);
        if (!in_box) {
          REQUIRE(count == 0);  // the box holds every covered row of the band
          continue;
        }
        const RowSpan got = spans[static_cast<std::size_t>(y - t.row0)];
        if (count == 0) {
          REQUIRE(got.begin >= got.end);
        } else {
          REQUIRE(last - first + 1 == count);  // one run per row: the reference agrees it is convex
          REQUIRE(got.begin == first);
          REQUIRE(got.end == last + 1);
          pixels += count;
        }
      }
    }
    // Both sides of the set-up's limits were exercised, and many boxes came near the 32-bit one.
    UNSCOPED_INFO("taken " << taken << ", declined " << declined << ", near the limit "
                           << near_limit << ", pixels " << pixels);
    CHECK(taken > 3000);
    CHECK(declined > 1000);
    CHECK(near_limit > 150);
    CHECK(pixels > 100000);
  }
}

TEST_CASE("small triangles: the set-up refuses what the kernel cannot do exactly",
          "[core][small_triangle]") {
  const SubpixelGrid grid(8);
  SmallTriangle t;
  const auto setup = [&](std::array<Vec2, 3> v, int width = 512, RowBand band = {0, 512}) {
    const std::array<FixedPoint, 3> p{grid.snap(v[0]), grid.snap(v[1]), grid.snap(v[2])};
    const i64 cross = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
    return small_triangle(p, grid_box(p, grid, FillRule::top_left), cross > 0, grid, width, band,
                          t);
  };
  CHECK(setup({Vec2{10, 10}, Vec2{20, 12}, Vec2{12, 30}}));
  CHECK(t.col0 == 10);
  CHECK(t.cols == 10);  // columns 10 … 19: a centre at x = 20 is the right end, never inside
  CHECK(t.row0 == 10);
  CHECK(t.rows == 20);
  // 32 columns are taken, 33 are not; 128 rows are taken, 129 are not.
  CHECK(setup({Vec2{0.5, 0}, Vec2{32.5, 1}, Vec2{1, 3}}));
  CHECK_FALSE(setup({Vec2{0.5, 0}, Vec2{33.5, 1}, Vec2{1, 3}}));
  CHECK(setup({Vec2{0, 0.5}, Vec2{1, 128.5}, Vec2{3, 1}}));
  CHECK_FALSE(setup({Vec2{0, 0.5}, Vec2{1, 129.5}, Vec2{3, 1}}));
  // A large triangle whose part on the canvas is a small box: its edge functions are not small.
  CHECK_FALSE(setup({Vec2{-5000, 3}, Vec2{10, 2}, Vec2{9, 9}}));
  // Nothing of the box on the canvas or in the band.
  CHECK_FALSE(setup({Vec2{600, 3}, Vec2{610, 2}, Vec2{609, 9}}));
  CHECK_FALSE(setup({Vec2{10, 10}, Vec2{20, 12}, Vec2{12, 30}}, 512, RowBand{40, 80}));
}
