// General polygons (concave, self-intersecting, with holes) under both winding rules: against the
// exact reference on hundreds of random polygons, hand-computed cases, tiling with a hole's
// filler, and agreement with the convex fill on convex input.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "counting_canvas.hpp"
#include "random.hpp"
#include "raster_compare.hpp"
#include "reference/exact_reference.hpp"
#include "src/scanline_fill.hpp"
#include "src/winding_fill.hpp"

namespace {

using scantrace::Color;
using scantrace::FillOptions;
using scantrace::Shading;
using scantrace::Vec2;
using scantrace::WindingRule;
using Contours = std::vector<std::vector<Vec2>>;

constexpr int kW = 64, kH = 48;

// Vertices on the fill's 1/256 grid (or whole pixels), so the reference decides on the same
// geometry as the fill.
Vec2 on_grid(Vec2 p, bool integer) {
  const double s = integer ? 1.0 : 256.0;
  return {std::round(p.x * s) / s, std::round(p.y * s) / s};
}

// A star-shaped (generally concave) contour around c: n vertices at increasing angles and random
// radii in [r0, r1]; reversed when `clockwise` is false.
std::vector<Vec2> star_shaped(sttest::Rng& rng, Vec2 c, int n, double r0, double r1, bool integer,
                              bool clockwise = true) {
  std::vector<Vec2> v;
  const double phase = rng.uniform(0, 6.3);
  for (int k = 0; k < n; ++k) {
    const double a = phase + 2 * std::numbers::pi * (k + rng.uniform(0.1, 0.9)) / n;
    const double r = rng.uniform(r0, r1);
    v.push_back(on_grid({c.x + r * std::cos(a), c.y + r * std::sin(a)}, integer));
  }
  if (!clockwise) std::reverse(v.begin(), v.end());
  return v;
}

// Random vertices in a box reaching a little past the canvas: self-intersecting almost surely.
std::vector<Vec2> tangle(sttest::Rng& rng, int n, bool integer) {
  std::vector<Vec2> v;
  for (int k = 0; k < n; ++k) v.push_back(on_grid(rng.point(-6, kW + 6, -6, kH + 6), integer));
  return v;
}

std::vector<Color> colours_for(sttest::Rng& rng, const Contours& c) {
  std::vector<Color> out;
  for (const auto& contour : c)
    for (std::size_t i = 0; i < contour.size(); ++i) out.push_back(rng.color());
  return out;
}

std::string describe(const Contours& c) {
  std::string s;
  for (const auto& contour : c) {
    s += "[";
    s += sttest::format_points(contour);
    s += "] ";
  }
  return s;
}

// Fills and compares with the reference: coverage exactly, colours within 1e-9 (Gouraud) or the
// mean (flat), and the pixel count reported.
std::string compare(const Contours& contours, const std::vector<Color>& colors, WindingRule rule,
                    Shading shading, int bits = 8) {
  scantrace::RgbImage img(kW, kH, sttest::kSentinel);
  FillOptions opt;
  opt.shading = shading;
  opt.winding_rule = rule;
  opt.subpixel_bits = bits;
  const scantrace::FillResult res =
      scantrace::fill_polygon_contours(img, std::span(contours), std::span(colors), opt);
  const auto ref = scantrace::reference::rasterize_contours(kW, kH, contours, colors, rule, bits);
  const Color flat = scantrace::reference::mean_color(colors);
  const bool gouraud = shading == Shading::gouraud;
  std::string diff = sttest::first_difference(
      img, ref, [&](int x, int y) { return gouraud ? ref.color_at(x, y) : flat; },
      1e-9);  // exact method: ~1e-12 before the float store
  if (diff.empty() && res.pixels != ref.count) {
    // Built by appending: GCC 12 raises a false -Wrestrict alarm on "literal" + std::string&&.
    diff = "fill reports ";
    diff += std::to_string(res.pixels);
    diff += " pixels, reference covers ";
    diff += std::to_string(ref.count);
  }
  return diff;
}

// `random_bits`: each polygon on a random subpixel grid (the fill and the reference snap alike).
void against_reference(std::uint64_t seed, int count, bool integer,
                       const std::function<Contours(sttest::Rng&)>& make,
                       bool random_bits = false) {
  sttest::Rng rng(seed);
  int failures = 0;
  for (int i = 0; i < count && failures < 3; ++i) {
    const Contours c = make(rng);
    const std::vector<Color> colors = colours_for(rng, c);
    const int bits = random_bits ? std::array{0, 2, 4, 8, 12}[rng.integer(0, 4)] : 8;
    for (WindingRule rule : {WindingRule::even_odd, WindingRule::non_zero})
      for (Shading shading : {Shading::gouraud, Shading::flat}) {
        const std::string diff = compare(c, colors, rule, shading, bits);
        INFO("polygon " << i << " " << describe(c) << " rule " << scantrace::to_string(rule)
                        << " bits " << bits << " shading " << scantrace::to_string(shading)
                        << (integer ? " integer" : " subpixel"));
        CHECK(diff == "");
        if (!diff.empty()) ++failures;
      }
  }
}

int covered(const scantrace::RgbImage& img) {
  int n = 0;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) n += !(img(x, y) == sttest::kSentinel);
  return n;
}

scantrace::RgbImage fill(const Contours& c, WindingRule rule, int w = kW, int h = kH) {
  scantrace::RgbImage img(w, h, sttest::kSentinel);
  std::vector<Color> colors;
  for (const auto& contour : c) colors.resize(colors.size() + contour.size(), Color{1, 0, 0});
  FillOptions opt;
  opt.winding_rule = rule;
  scantrace::fill_polygon_contours(img, std::span(c), std::span(colors), opt);
  return img;
}

}  // namespace

TEST_CASE("concave polygons agree with the exact reference under both winding rules", "[winding]") {
  for (bool integer : {true, false})
    against_reference(integer ? 11 : 12, 120, integer, [&](sttest::Rng& rng) {
      return Contours{star_shaped(rng, rng.point(15, 50, 12, 36),
                                  static_cast<int>(rng.integer(5, 16)), 3, 26, integer,
                                  rng.integer(0, 1) == 1)};
    });
}

TEST_CASE("self-intersecting polygons agree with the exact reference under both winding rules",
          "[winding]") {
  for (bool integer : {true, false})
    against_reference(integer ? 21 : 22, 120, integer, [&](sttest::Rng& rng) {
      return Contours{tangle(rng, static_cast<int>(rng.integer(4, 12)), integer)};
    });
}

TEST_CASE(
    "polygons on other subpixel grids and with vertices a billion pixels away agree with "
    "the exact reference",
    "[winding]") {
  against_reference(
      61, 150, false,
      [&](sttest::Rng& rng) {
        return Contours{tangle(rng, static_cast<int>(rng.integer(4, 9)), false)};
      },
      true);
  // Far vertices: the fill starts edges at the first visible row, exactly (docs/design.md §3).
  against_reference(62, 100, false, [&](sttest::Rng& rng) {
    std::vector<Vec2> v = tangle(rng, static_cast<int>(rng.integer(4, 8)), false);
    const double far = rng.integer(0, 1) ? 1e9 : -1e9;
    v[0] = rng.integer(0, 1) ? Vec2{far, v[0].y} : Vec2{v[0].x, far};
    return Contours{v};
  });
}

TEST_CASE("polygons with holes and several contours agree with the exact reference", "[winding]") {
  for (bool integer : {true, false})
    against_reference(integer ? 31 : 32, 120, integer, [&](sttest::Rng& rng) {
      const Vec2 c = rng.point(22, 42, 18, 30);
      Contours out{star_shaped(rng, c, static_cast<int>(rng.integer(4, 10)), 14, 22, integer)};
      // A hole, running either way round (a hole under even-odd; under non-zero only when
      // reversed), and sometimes a third contour overlapping the others.
      out.push_back(star_shaped(rng, c, static_cast<int>(rng.integer(3, 8)), 3, 10, integer,
                                rng.integer(0, 1) == 1));
      if (rng.integer(0, 2) == 0) out.push_back(tangle(rng, 4, integer));
      return out;
    });
}

TEST_CASE("a pentagram: even-odd leaves the centre empty, non-zero fills it", "[winding]") {
  // Vertices every 144° on a circle of radius 20 around (32, 24), no vertex on a pixel centre row.
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k) {
    const double a = -std::numbers::pi / 2 + 0.1 + k * 4 * std::numbers::pi / 5;
    star.push_back({32 + 20 * std::cos(a), 24.3 + 20 * std::sin(a)});
  }
  const auto eo = fill({star}, WindingRule::even_odd), nz = fill({star}, WindingRule::non_zero);
  // The central pentagon (inradius 20·cos(72°)... ≈ 6.2 px) has winding 2: empty under even-odd.
  for (int y = 22; y <= 26; ++y)
    for (int x = 30; x <= 34; ++x) {
      CHECK(eo(x, y) == sttest::kSentinel);
      CHECK(!(nz(x, y) == sttest::kSentinel));
    }
  // The points (winding 1) are filled under both, e.g. near the top vertex (32.., 4.3..).
  CHECK(!(eo(33, 9) == sttest::kSentinel));
  CHECK(!(nz(33, 9) == sttest::kSentinel));
  // Non-zero fills exactly what even-odd fills plus the centre.
  int only_nz = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const bool e = !(eo(x, y) == sttest::kSentinel), n = !(nz(x, y) == sttest::kSentinel);
      CHECK((!e || n));
      only_nz += n && !e;
    }
  CHECK(only_nz > 25);
}

TEST_CASE("a square with a square hole", "[winding]") {
  const std::vector<Vec2> outer{{10, 10}, {30, 10}, {30, 30}, {10, 30}};
  const std::vector<Vec2> hole_reversed{{15, 15}, {15, 25}, {25, 25}, {25, 15}};
  const std::vector<Vec2> hole_same{{15, 15}, {25, 15}, {25, 25}, {15, 25}};
  // Rows 10..29, columns 10..29 (400 pixels) minus rows and columns 15..24 (100 pixels).
  auto is_ring = [](int x, int y) {
    const bool in_outer = x >= 10 && x < 30 && y >= 10 && y < 30;
    const bool in_hole = x >= 15 && x < 25 && y >= 15 && y < 25;
    return in_outer && !in_hole;
  };
  auto is_square = [](int x, int y) { return x >= 10 && x < 30 && y >= 10 && y < 30; };
  const auto eo_rev = fill({outer, hole_reversed}, WindingRule::even_odd);
  const auto nz_rev = fill({outer, hole_reversed}, WindingRule::non_zero);
  const auto eo_same = fill({outer, hole_same}, WindingRule::even_odd);
  const auto nz_same = fill({outer, hole_same}, WindingRule::non_zero);
  CHECK(covered(eo_rev) == 300);
  CHECK(covered(nz_rev) == 300);
  CHECK(covered(eo_same) == 300);
  CHECK(covered(nz_same) == 400);  // winding 2 inside the hole: non-zero fills it
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      CHECK(!(eo_rev(x, y) == sttest::kSentinel) == is_ring(x, y));
      CHECK(!(nz_rev(x, y) == sttest::kSentinel) == is_ring(x, y));
      CHECK(!(nz_same(x, y) == sttest::kSentinel) == is_square(x, y));
    }
}

TEST_CASE("a bow-tie fills its two triangles under both rules", "[winding]") {
  // (0,0) → (20,20) → (20,0) → (0,20): the diagonals cross at (10, 10). On row y the left lobe
  // covers x in [0, min(y, 20 − y)) and the right one [max(y, 20 − y), 20): 100 + 100 pixels.
  const std::vector<Vec2> tie{{0, 0}, {20, 20}, {20, 0}, {0, 20}};
  for (WindingRule rule : {WindingRule::even_odd, WindingRule::non_zero}) {
    const auto img = fill({tie}, rule, 24, 24);
    CHECK(covered(img) == 200);
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 24; ++x) {
        const bool want =
            y < 20 && ((x < std::min(y, 20 - y)) || (x >= std::max(y, 20 - y) && x < 20));
        INFO("pixel " << x << ", " << y);
        CHECK(!(img(x, y) == sttest::kSentinel) == want);
      }
  }
}

TEST_CASE("a polygon with a hole and a polygon filling the hole tile: each pixel once",
          "[winding]") {
  sttest::Rng rng(41);
  for (int i = 0; i < 150; ++i) {
    const bool integer = i % 2 == 0;
    const Vec2 c = rng.point(22, 42, 18, 30);
    const auto outer = star_shaped(rng, c, static_cast<int>(rng.integer(4, 10)), 14, 22, integer);
    // The outer contour is star-shaped around c (its fan triangles c, v_k, v_k+1 cover it), so
    // a copy scaled down about c lies inside it.
    const double scale = rng.uniform(0.2, 0.6);
    std::vector<Vec2> hole;
    for (const Vec2& v : outer)
      hole.push_back(on_grid({c.x + scale * (v.x - c.x), c.y + scale * (v.y - c.y)}, integer));
    const WindingRule rule = i % 3 == 0 ? WindingRule::non_zero : WindingRule::even_odd;
    auto reversed = hole;
    std::reverse(reversed.begin(), reversed.end());
    const Contours ring{outer, rule == WindingRule::non_zero ? reversed : hole};
    const Contours filler{hole};
    sttest::CountingCanvas canvas(kW, kH);
    scantrace::WindingScratch s;
    FillOptions opt;
    opt.winding_rule = rule;
    std::vector<Color> ring_colours(outer.size() + hole.size()), filler_colours(hole.size());
    scantrace::fill_polygon_contours(canvas, std::span(ring), std::span(ring_colours), opt, s);
    scantrace::fill_polygon_contours(canvas, std::span(filler), std::span(filler_colours), opt, s);
    const auto whole = scantrace::reference::rasterize_contours(kW, kH, Contours{outer}, {},
                                                                WindingRule::even_odd, 8);
    INFO("outer " << sttest::format_points(outer) << " hole " << sttest::format_points(hole));
    int wrong = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) wrong += canvas.count(x, y) != (whole.at(x, y) ? 1 : 0);
    CHECK(wrong == 0);
    CHECK(canvas.out_of_bounds() == 0);
  }
}

TEST_CASE("a convex polygon fills the same pixels, in the same colours, as the convex fill",
          "[winding]") {
  sttest::Rng rng(51);
  for (int i = 0; i < 200; ++i) {
    const bool integer = i % 2 == 0;
    // Convex: vertices on an ellipse at increasing angles.
    const int n = static_cast<int>(rng.integer(3, 9));
    const Vec2 c = rng.point(-10, kW + 10, -10, kH + 10);
    const double rx = rng.uniform(1, 40), ry = rng.uniform(1, 40), phase = rng.uniform(0, 6.3);
    std::vector<Vec2> v;
    std::vector<double> angles;
    for (int k = 0; k < n; ++k) angles.push_back(rng.uniform(0, 2 * std::numbers::pi));
    std::sort(angles.begin(), angles.end());
    for (double a : angles)
      v.push_back(
          on_grid({c.x + rx * std::cos(a + phase), c.y + ry * std::sin(a + phase)}, integer));
    std::vector<Color> colors;
    for (int k = 0; k < n; ++k) colors.push_back(rng.color());
    for (WindingRule rule : {WindingRule::even_odd, WindingRule::non_zero}) {
      scantrace::RgbImage convex(kW, kH, sttest::kSentinel), general(kW, kH, sttest::kSentinel);
      FillOptions opt;
      opt.winding_rule = rule;
      scantrace::fill_convex_polygon(convex, std::span<const Vec2>(v),
                                     std::span<const Color>(colors), opt);
      const Contours one{v};
      scantrace::fill_polygon_contours(general, std::span(one), std::span(colors), opt);
      INFO("polygon " << sttest::format_points(v));
      int differ = 0;
      for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
          const scantrace::Rgb32f a = convex(x, y), b = general(x, y);
          if ((a == sttest::kSentinel) != (b == sttest::kSentinel) || std::fabs(a.r - b.r) > 1e-5 ||
              std::fabs(a.g - b.g) > 1e-5 || std::fabs(a.b - b.b) > 1e-5)
            ++differ;
        }
      CHECK(differ == 0);
    }
  }
}

TEST_CASE("general polygons reject the closed rule and the halfspace method", "[winding]") {
  const Contours square{{{1, 1}, {5, 1}, {5, 5}, {1, 5}}};
  const std::vector<Color> colors(4);
  scantrace::RgbImage img(8, 8);
  FillOptions closed;
  closed.fill_rule = scantrace::FillRule::closed;
  CHECK_THROWS_WITH(
      scantrace::fill_polygon_contours(img, std::span(square), std::span(colors), closed),
      Catch::Contains("closed fill rule"));
  FillOptions halfspace;
  halfspace.method = scantrace::Method::halfspace;
  CHECK_THROWS_WITH(
      scantrace::fill_polygon_contours(img, std::span(square), std::span(colors), halfspace),
      Catch::Contains("halfspace"));
}

TEST_CASE("every stepper fills a rectilinear polygon with a hole identically", "[winding]") {
  // Axis-aligned edges cross rows at whole-pixel x, where no method can round the wrong way:
  // exact, double and float must give the same pixels (an L-shaped outline with a square hole).
  const Contours shape{{{3, 3}, {40, 3}, {40, 20}, {20, 20}, {20, 40}, {3, 40}},
                       {{8, 8}, {15, 8}, {15, 15}, {8, 15}}};
  std::vector<Color> colors(10, Color{0.5, 0.5, 0.5});
  for (WindingRule rule : {WindingRule::even_odd, WindingRule::non_zero}) {
    const auto want = scantrace::reference::rasterize_contours(kW, kH, shape, colors, rule, 8);
    for (scantrace::Method m :
         {scantrace::Method::exact, scantrace::Method::double64, scantrace::Method::float32}) {
      scantrace::RgbImage img(kW, kH, sttest::kSentinel);
      FillOptions opt;
      opt.winding_rule = rule;
      opt.method = m;
      scantrace::fill_polygon_contours(img, std::span(shape), std::span(colors), opt);
      INFO("method " << scantrace::to_string(m) << " rule " << scantrace::to_string(rule));
      CHECK(sttest::first_difference(
                img, want,
                [](int, int) {
                  return Color{0.5, 0.5, 0.5};
                },
                1e-6) == "");
    }
  }
}
