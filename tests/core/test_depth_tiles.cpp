// The z-buffer's early rejection (issue 19): DepthTiles's bookkeeping against a brute-force scan
// of a depth buffer, and DepthPlane::lower_bound against the depths the plane gives at every
// pixel of the box, rounding included.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "src/depth_plane.hpp"
#include "src/fast/depth_tiles.hpp"
#include "src/splitmix64.hpp"

using namespace scantrace;

TEST_CASE("depth tiles: a box is all nearer exactly when a scan of its tiles says so",
          "[depth_tiles]") {
  SplitMix64 rng(7);
  constexpr int W = 37, H = 29;  // tiles cut by the image's edges
  const double inf = std::numeric_limits<double>::infinity();
  // Per pixel: the depth stored, and the largest depth ever written (the tiles' bound is the
  // largest of these over the tile; a pixel written again is written nearer).
  std::vector<double> z(W * H, inf), ever(W * H, -inf);
  DepthTiles tiles;
  tiles.reset(W, H);
  int all_nearer = 0;
  for (int step = 0; step < 20000; ++step) {
    const int x = static_cast<int>(rng.next() % W), y = static_cast<int>(rng.next() % H);
    const double d = std::floor(rng.uniform(0, 50));
    if (d < z[y * W + x]) {
      tiles.wrote(x, y, z[y * W + x], d);
      z[y * W + x] = d;
      ever[y * W + x] = std::max(ever[y * W + x], d);
    }
    // A box, partly off the image at times, and a depth to compare with.
    const int x0 = static_cast<int>(rng.next() % (W + 10)) - 5;
    const int y0 = static_cast<int>(rng.next() % (H + 10)) - 5;
    const int x1 = x0 + static_cast<int>(rng.next() % 12);
    const int y1 = y0 + static_cast<int>(rng.next() % 12);
    const double nearest = std::floor(rng.uniform(0, 60));
    // The contract, by brute force over every pixel of the tiles the clipped box touches.
    const int cx0 = std::max(x0, 0), cy0 = std::max(y0, 0), cx1 = std::min(x1, W - 1),
              cy1 = std::min(y1, H - 1);
    bool expect = cx0 <= cx1 && cy0 <= cy1;
    for (int ty = cy0 / 8; expect && ty <= cy1 / 8; ++ty)
      for (int tx = cx0 / 8; expect && tx <= cx1 / 8; ++tx)
        for (int py = ty * 8; py < std::min(H, ty * 8 + 8); ++py)
          for (int px = tx * 8; px < std::min(W, tx * 8 + 8); ++px)
            if (z[py * W + px] == inf || !(ever[py * W + px] < nearest)) expect = false;
    INFO("step " << step << ", box " << x0 << "," << y0 << " - " << x1 << "," << y1);
    REQUIRE(tiles.all_nearer(x0, y0, x1, y1, nearest) == expect);
    all_nearer += expect;
  }
  CHECK(all_nearer > 100);
}

TEST_CASE("depth plane: lower_bound is at or below the depth at every pixel of the box",
          "[depth_tiles]") {
  SplitMix64 rng(11);
  long long tight = 0;
  for (int i = 0; i < 20000; ++i) {
    // Planes from slivers to large triangles, depths from tiny to huge, vertices on the 1/256 grid.
    const double spread = i % 4 == 0 ? 1e6 : 300;
    std::array<Vec2, 3> p;
    for (Vec2& v : p)
      v = {std::round(rng.uniform(-spread, spread) * 256) / 256,
           std::round(rng.uniform(-spread, spread) * 256) / 256};
    if (i % 3 == 0)
      p[2] = {p[0].x + (p[1].x - p[0].x) * 0.5 + 1.0 / 256, p[0].y + (p[1].y - p[0].y) * 0.5};
    const double scale = i % 5 == 0 ? 1e-3 : i % 5 == 1 ? 1e9 : 10;
    const std::array<double, 3> d{rng.uniform(0, scale), rng.uniform(0, scale),
                                  rng.uniform(0, scale)};
    const DepthPlane plane = DepthPlane::through(p, d);
    const int x0 = static_cast<int>(rng.uniform(-20, 500)),
              y0 = static_cast<int>(rng.uniform(-20, 500));
    const int x1 = x0 + static_cast<int>(rng.next() % 40),
              y1 = y0 + static_cast<int>(rng.next() % 40);
    const double bound = plane.lower_bound(x0, y0, x1, y1);
    double lowest = std::numeric_limits<double>::infinity();
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) lowest = std::min(lowest, plane.at(x, y));
    INFO("case " << i);
    REQUIRE(bound <= lowest);
    // Not uselessly low: within a relative 1e-12 of the true minimum's size in most cases.
    if (std::isfinite(bound) && lowest - bound <= 1e-12 * (std::fabs(lowest) + 1)) ++tight;
  }
  CHECK(tight > 15000);
}
