// Convex polygons of 4..12 vertices through fill_convex_polygon: coverage against the reference's
// half-plane test, and Gouraud colours against an affine colour field, which the edge-then-span
// interpolation must reproduce exactly (both stages are linear).
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "random.hpp"
#include "raster_compare.hpp"
#include "reference_raster.hpp"
#include "src/scanline_fill.hpp"

namespace {

using scantrace::Color;
using scantrace::FillOptions;
using scantrace::FillRule;
using scantrace::RgbImage;
using scantrace::Shading;
using scantrace::Vec2;
using sttest::Rng;

// A regular n-gon with random centre, radius and rotation, listed clockwise or counter-clockwise;
// with `grid` > 0 the vertices are rounded to multiples of 1/grid (which puts centres on edges).
std::vector<Vec2> regular_polygon(Rng& r, int n, Vec2 centre, double radius, double grid) {
  const double phase = r.uniform(0, 2 * std::numbers::pi);
  std::vector<Vec2> p;
  for (int k = 0; k < n; ++k) {
    const double a = phase + 2 * std::numbers::pi * k / n;
    Vec2 v{centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)};
    if (grid > 0) v = {std::round(v.x * grid) / grid, std::round(v.y * grid) / grid};
    p.push_back(v);
  }
  if (r.coin()) std::reverse(p.begin(), p.end());
  return p;
}

// Strictly convex after snapping: every turn has the same sign (rounding must not have folded it).
bool strictly_convex(const std::vector<Vec2>& p) {
  int sign = 0;
  for (std::size_t i = 0, n = p.size(); i < n; ++i) {
    const sttest::GridPt a = sttest::ref_snap(p[i], 8), b = sttest::ref_snap(p[(i + 1) % n], 8),
                         c = sttest::ref_snap(p[(i + 2) % n], 8);
    const sttest::i128 turn = static_cast<sttest::i128>(b.x - a.x) * (c.y - b.y) -
                              static_cast<sttest::i128>(b.y - a.y) * (c.x - b.x);
    const int s = turn > 0 ? 1 : turn < 0 ? -1 : 0;
    if (s == 0 || (sign != 0 && s != sign)) return false;
    sign = s;
  }
  return true;
}

struct Affine {
  std::array<double, 3> a, b, c;  // colour channel k = a[k]·x + b[k]·y + c[k]
  Color at(double x, double y) const {
    return {a[0] * x + b[0] * y + c[0], a[1] * x + b[1] * y + c[1], a[2] * x + b[2] * y + c[2]};
  }
};

// A random affine colour field staying within [0, 1] over a disc of `radius` around `centre`.
Affine random_field(Rng& r, Vec2 centre, double radius) {
  Affine f;
  for (int k = 0; k < 3; ++k) {
    const double angle = r.uniform(0, 2 * std::numbers::pi), slope = r.uniform(0, 0.45) / radius;
    f.a[k] = slope * std::cos(angle);
    f.b[k] = slope * std::sin(angle);
    f.c[k] = 0.5 - f.a[k] * centre.x - f.b[k] * centre.y;
  }
  return f;
}

}  // namespace

TEST_CASE("convex polygons agree with the reference", "[polygon]") {
  Rng rng(0x6001);
  int failures = 0, tested = 0;
  for (const FillRule rule : {FillRule::top_left, FillRule::closed}) {
    for (int i = 0; i < 600 && failures < 3; ++i) {
      const int w = i % 2 ? 64 : 200, h = i % 2 ? 48 : 150;
      const int n = static_cast<int>(rng.integer(4, 12));
      const double radius = std::array{1.5, 6.0, 25.0, 120.0}[rng.integer(0, 3)];
      // A third on integers, a third on quarters, a third anywhere.
      const double grid = std::array{1.0, 4.0, 0.0}[i % 3];
      if (grid > 0 && radius < 20) continue;  // rounding small polygons would fold them
      const std::vector<Vec2> p =
          regular_polygon(rng, n, rng.point(-10, w + 10, -10, h + 10), radius, grid);
      if (!strictly_convex(p)) continue;
      ++tested;
      std::vector<Color> c;
      for (int k = 0; k < n; ++k) c.push_back(rng.color());

      RgbImage img(w, h, sttest::kSentinel);
      const scantrace::FillResult res =
          scantrace::fill_convex_polygon(img, p, c, FillOptions{Shading::flat, rule});
      const sttest::RefRaster ref = sttest::ref_rasterize(
          w, h, p, {},
          rule == FillRule::closed ? sttest::RefRule::closed : sttest::RefRule::top_left);
      const Color flat = sttest::mean_color(c);
      const std::string diff = sttest::first_difference(
          img, ref, [&](int, int) { return flat; }, 1e-6);
      INFO(n << "-gon " << sttest::format_points(p) << "rule " << scantrace::to_string(rule));
      CHECK(diff == "");
      CHECK(res.pixels == ref.count);
      failures += !diff.empty();
    }
  }
  CHECK(tested >= 700);  // the skips above must not have emptied the test
}

TEST_CASE("Gouraud polygons reproduce an affine colour field", "[polygon][gouraud]") {
  Rng rng(0x6002);
  int failures = 0, tested = 0;
  for (int i = 0; i < 400 && failures < 3; ++i) {
    const int n = i % 3 == 0 ? 4 : static_cast<int>(rng.integer(4, 12));
    const double radius = rng.uniform(3, 90);
    const Vec2 centre = rng.point(-20, 220, -20, 170);
    // On the 1/256 grid the vertices snap to themselves, so the field's vertex colours are the
    // field at the very points the fill interpolates between.
    std::vector<Vec2> p = regular_polygon(rng, n, centre, radius, 256);
    if (i % 3 == 0)  // irregular quads: a random point in each quadrant of the circle
      for (int k = 0; k < 4; ++k) {
        const double a = (k + rng.uniform(0.1, 0.9)) * std::numbers::pi / 2;
        const double rr = radius * rng.uniform(0.4, 1.0);
        p[k] = {std::round((centre.x + rr * std::cos(a)) * 256) / 256,
                std::round((centre.y + rr * std::sin(a)) * 256) / 256};
      }
    if (!strictly_convex(p)) continue;
    ++tested;
    const Affine field = random_field(rng, centre, radius);
    std::vector<Color> c;
    for (const Vec2& v : p) c.push_back(field.at(v.x, v.y));

    for (const FillRule rule : {FillRule::top_left, FillRule::closed}) {
      RgbImage img(200, 150, sttest::kSentinel);
      const scantrace::FillResult res =
          scantrace::fill_convex_polygon(img, p, c, FillOptions{Shading::gouraud, rule});
      const sttest::RefRaster ref = sttest::ref_rasterize(
          200, 150, p, {},
          rule == FillRule::closed ? sttest::RefRule::closed : sttest::RefRule::top_left);
      const std::string diff = sttest::first_difference(
          img, ref, [&](int x, int y) { return field.at(x, y); }, 1e-4);
      INFO(n << "-gon " << sttest::format_points(p) << "rule " << scantrace::to_string(rule));
      CHECK(diff == "");
      CHECK(res.pixels == ref.count);
      failures += !diff.empty();
    }
  }
  CHECK(tested >= 350);
}
