// Design.md §3's vertex-order invariance for convex polygons of more than three vertices: every
// rotation of the vertex list and its reversal give the same image, bit for bit (colours kept in
// double), and that image covers exactly the pixels of the exact reference
// (src/exact_reference.hpp), for both fill rules and both shadings.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "double_canvas.hpp"
#include "random.hpp"
#include "reference_raster.hpp"
#include "reference/exact_reference.hpp"
#include "src/scanline_fill.hpp"

namespace {

using scantrace::Color;
using scantrace::FillOptions;
using scantrace::FillRule;
using scantrace::Shading;
using scantrace::Vec2;
using sttest::Rng;

using DoubleCanvas = sttest::DoubleCanvas;

// n points on a circle at sorted random angles (a convex polygon), rounded to multiples of
// 1/grid: integers put centres on edges and vertices, 2^16 keeps them fractional.
std::vector<Vec2> convex_polygon(Rng& r, int n, Vec2 centre, double radius, double grid) {
  std::vector<double> angles;
  for (int k = 0; k < n; ++k) angles.push_back(r.uniform(0, 2 * std::numbers::pi));
  std::sort(angles.begin(), angles.end());
  std::vector<Vec2> p;
  for (double a : angles)
    p.push_back({std::round((centre.x + radius * std::cos(a)) * grid) / grid,
                 std::round((centre.y + radius * std::sin(a)) * grid) / grid});
  return p;
}

// Every turn strictly the same way on the fill's grid (rounding may have folded or merged).
bool strictly_convex(const std::vector<Vec2>& p, int bits) {
  int sign = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const sttest::GridPt a = sttest::ref_snap(p[i], bits),
                         b = sttest::ref_snap(p[(i + 1) % n], bits),
                         c = sttest::ref_snap(p[(i + 2) % n], bits);
    const sttest::i128 turn = static_cast<sttest::i128>(b.x - a.x) * (c.y - b.y) -
                              static_cast<sttest::i128>(b.y - a.y) * (c.x - b.x);
    const int s = turn > 0 ? 1 : turn < 0 ? -1 : 0;
    if (s == 0 || (sign != 0 && s != sign)) return false;
    sign = s;
  }
  return true;
}

DoubleCanvas fill(const std::vector<Vec2>& p, const std::vector<Color>& c, const FillOptions& opt,
                  int w, int h) {
  DoubleCanvas canvas(w, h);
  scantrace::FillScratch scratch;
  scantrace::fill_polygon(canvas, scantrace::PolygonInput{p, c, 0, {}}, opt, scratch);
  return canvas;
}

}  // namespace

TEST_CASE("convex polygons of 4..9 vertices: every rotation and the reversal give one image",
          "[invariance][polygon]") {
  Rng rng(0x20b4);
  const int w = 48, h = 40;
  int tested = 0, orders = 0;
  for (int i = 0; i < 240; ++i) {
    const int n = static_cast<int>(rng.integer(4, 9));
    const double grid = i % 2 ? 1.0 : 65536.0;
    const double radius = i % 2 ? rng.uniform(8, 22) : rng.uniform(1.5, 22);
    const std::vector<Vec2> p =
        convex_polygon(rng, n, rng.point(-4, w + 4, -4, h + 4), radius, grid);
    const FillOptions opt{i % 4 < 2 ? Shading::gouraud : Shading::flat,
                          i % 8 < 4 ? FillRule::top_left : FillRule::closed};
    if (!strictly_convex(p, opt.subpixel_bits)) continue;
    ++tested;
    std::vector<Color> c;
    for (int k = 0; k < n; ++k) c.push_back(rng.color());

    const DoubleCanvas first = fill(p, c, opt, w, h);
    // The exact reference's coverage of the same polygon on the fill's grid.
    const scantrace::reference::Raster ref =
        scantrace::reference::rasterize(w, h, p, {}, opt.fill_rule, opt.subpixel_bits);
    int coverage_differs = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) coverage_differs += first.written(x, y) != ref.at(x, y);
    INFO(n << "-gon, " << scantrace::to_string(opt.fill_rule) << ", "
           << scantrace::to_string(opt.shading) << ", " << ref.count << " pixels");
    CHECK(coverage_differs == 0);

    for (const bool reversed : {false, true}) {
      for (int k = 0; k < n; ++k) {
        std::vector<Vec2> q = p;
        std::vector<Color> d = c;
        std::rotate(q.begin(), q.begin() + k, q.end());
        std::rotate(d.begin(), d.begin() + k, d.end());
        if (reversed) {
          std::reverse(q.begin(), q.end());
          std::reverse(d.begin(), d.end());
        }
        INFO("rotation " << k << (reversed ? ", reversed" : ""));
        CHECK(fill(q, d, opt, w, h) == first);
        ++orders;
      }
    }
  }
  CHECK(tested >= 150);  // rounding must not have emptied the test
  CHECK(orders >= 1000);
}
