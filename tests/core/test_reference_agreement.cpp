// The scanline fill against the brute-force reference on thousands of random triangles: every
// pixel's coverage under both fill rules, Gouraud colours against exact barycentric
// interpolation, flat colours against the mean, and the pixel count the fill reports.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>

#include "random.hpp"
#include "raster_compare.hpp"
#include "reference_raster.hpp"
#include "src/scanline_fill.hpp"

namespace {

using scantrace::Color;
using scantrace::FillOptions;
using scantrace::FillRule;
using scantrace::Shading;
using scantrace::Vec2;
using sttest::Rng;
using Triangle = std::array<Vec2, 3>;
using Generator = std::function<Triangle(Rng&, int width, int height)>;

struct CanvasSize {
  int width, height;
};
constexpr std::array<CanvasSize, 3> kCanvases{{{64, 48}, {200, 150}, {7, 5}}};

// Fills `count` random triangles of one family on every canvas, in the given mode, and compares
// each with the reference. Stops after a few failing triangles to keep the report readable.
void agree_with_reference(std::uint64_t seed, int count, const Generator& make, FillRule rule,
                          Shading shading, bool random_bits) {
  Rng rng(seed);
  int failures = 0;
  for (const CanvasSize cv : kCanvases) {
    for (int i = 0; i < count && failures < 3; ++i) {
      const Triangle v = make(rng, cv.width, cv.height);
      const std::array<Color, 3> c{rng.color(), rng.color(), rng.color()};
      const int b = random_bits ? std::array{0, 1, 4, 8, 12}[rng.integer(0, 4)] : 8;

      scantrace::RgbImage img(cv.width, cv.height, sttest::kSentinel);
      const FillOptions opt{shading, rule, b};
      const scantrace::FillResult res = scantrace::fill_triangle(img, v, c, opt);
      const sttest::RefRaster ref = sttest::ref_rasterize(
          cv.width, cv.height, v, c,
          rule == FillRule::closed ? sttest::RefRule::closed : sttest::RefRule::top_left, b);

      const Color flat = sttest::mean_color(c);
      const bool gouraud = shading == Shading::gouraud;
      const std::string diff = sttest::first_difference(
          img, ref, [&](int x, int y) { return gouraud ? ref.color_at(x, y) : flat; },
          1e-9);  // exact method: ~1e-12 before the float store

      INFO("canvas " << cv.width << "x" << cv.height << ", subpixel bits " << b << ", triangle "
                     << sttest::format_points(v) << "colors " << sttest::format_color(c[0]) << " "
                     << sttest::format_color(c[1]) << " " << sttest::format_color(c[2]));
      CHECK(diff == "");
      CHECK(res.pixels == ref.count);
      CHECK(res.rows <= cv.height);
      // A skipped triangle must be one that covers no pixel centre.
      if (res.skipped != scantrace::SkipReason::none) CHECK(ref.count == 0);
      if (!diff.empty() || res.pixels != ref.count) ++failures;
    }
  }
}

void all_modes(std::uint64_t seed, int count, const Generator& make, bool random_bits = false) {
  SECTION("top-left, flat") {
    agree_with_reference(seed, count, make, FillRule::top_left, Shading::flat, random_bits);
  }
  SECTION("top-left, gouraud") {
    agree_with_reference(seed, count, make, FillRule::top_left, Shading::gouraud, random_bits);
  }
  SECTION("closed, flat") {
    agree_with_reference(seed, count, make, FillRule::closed, Shading::flat, random_bits);
  }
  SECTION("closed, gouraud") {
    agree_with_reference(seed, count, make, FillRule::closed, Shading::gouraud, random_bits);
  }
}

double integer(Rng& r, long long lo, long long hi) {
  return static_cast<double>(r.integer(lo, hi));
}

}  // namespace

// Integer vertices put many pixel centres exactly on edges and on vertices: the tie rule decides.
TEST_CASE("reference agreement: small triangles with integer vertices", "[reference]") {
  all_modes(0x1001, 400, [](Rng& r, int w, int h) {
    const double bx = integer(r, -4, w + 4), by = integer(r, -4, h + 4);
    Triangle t;
    for (Vec2& p : t) p = {bx + integer(r, -8, 8), by + integer(r, -8, 8)};
    return t;
  });
}

TEST_CASE("reference agreement: large triangles with integer vertices", "[reference]") {
  all_modes(0x1002, 150, [](Rng& r, int w, int h) {
    Triangle t;
    for (Vec2& p : t) p = {integer(r, -w / 2, 3 * w / 2), integer(r, -h / 2, 3 * h / 2)};
    return t;
  });
}

// Halves and quarters are on the grid and put centres on edges at fractional slopes; multiples of
// 1/512 are exact snapping ties (ties go up).
TEST_CASE("reference agreement: vertices on binary fractions", "[reference]") {
  all_modes(0x1003, 300, [](Rng& r, int w, int h) {
    const double denom = std::array{2.0, 4.0, 512.0}[r.integer(0, 2)];
    const double bx = integer(r, 0, w), by = integer(r, 0, h);
    Triangle t;
    const long long k = 12 * static_cast<long long>(denom);  // offsets up to 12 px
    for (Vec2& p : t) p = {bx + integer(r, -k, k) / denom, by + integer(r, -k, k) / denom};
    return t;
  });
}

TEST_CASE("reference agreement: fractional vertices of all sizes", "[reference]") {
  all_modes(0x1004, 300, [](Rng& r, int w, int h) {
    const double size = std::array{3.0, 15.0, 60.0, 250.0}[r.integer(0, 3)];
    const Vec2 c = r.point(-10, w + 10, -10, h + 10);
    Triangle t;
    for (Vec2& p : t) p = r.point(c.x - size, c.x + size, c.y - size, c.y + size);
    return t;
  });
}

TEST_CASE("reference agreement: sub-pixel triangles", "[reference]") {
  all_modes(0x1005, 500, [](Rng& r, int w, int h) {
    const Vec2 c = r.point(-1, w + 1, -1, h + 1);
    Triangle t;
    for (Vec2& p : t) p = r.point(c.x - 1.2, c.x + 1.2, c.y - 1.2, c.y + 1.2);
    return t;
  });
}

// Long and thinner than a pixel: rows whose span holds zero or one centre.
TEST_CASE("reference agreement: slivers", "[reference]") {
  all_modes(0x1006, 300, [](Rng& r, int w, int h) {
    const Vec2 a = r.point(-5, w + 5, -5, h + 5), b = r.point(-5, w + 5, -5, h + 5);
    const double t = r.unit(), width = r.uniform(1e-4, 0.8);
    const double len = std::hypot(b.x - a.x, b.y - a.y) + 1e-9;
    const Vec2 m{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
    return Triangle{a, b, Vec2{m.x - (b.y - a.y) / len * width, m.y + (b.x - a.x) / len * width}};
  });
}

TEST_CASE("reference agreement: canvas-sized and partly off-canvas triangles", "[reference]") {
  all_modes(0x1007, 200, [](Rng& r, int w, int h) {
    Triangle t;
    for (Vec2& p : t) p = r.point(-1.0 * w, 2.0 * w, -1.0 * h, 2.0 * h);
    return t;
  });
}

// Beyond one side of the canvas; the boundary case x_max == 0 has its right edge on the centres of
// column 0, which the top-left rule excludes and the closed rule includes.
TEST_CASE("reference agreement: triangles beyond a canvas side", "[reference]") {
  all_modes(0x1008, 200, [](Rng& r, int w, int h) {
    Triangle t;
    const long long side = r.integer(0, 3);
    for (Vec2& p : t) {
      const double out = r.coin() ? -integer(r, 0, 30) : r.uniform(-30, 0);
      const double along = r.uniform(-10, std::max(w, h) + 10.0);
      switch (side) {
        case 0:
          p = {out, along};
          break;  // left
        case 1:
          p = {w - 1 - out, along};
          break;  // right
        case 2:
          p = {along, out};
          break;  // top
        default:
          p = {along, h - 1 - out};
          break;  // bottom
      }
    }
    return t;
  });
}

TEST_CASE("reference agreement: other subpixel resolutions", "[reference]") {
  all_modes(
      0x1009, 250,
      [](Rng& r, int w, int h) {
        const double size = std::array{2.0, 10.0, 80.0}[r.integer(0, 2)];
        const Vec2 c = r.point(0, w, 0, h);
        Triangle t;
        for (Vec2& p : t) p = r.point(c.x - size, c.x + size, c.y - size, c.y + size);
        return t;
      },
      true);
}
