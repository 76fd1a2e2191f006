// Design.md §3 pins two symmetries of the result: it does not depend on the order in which the
// vertices are given, and translating by whole pixels translates it.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "double_canvas.hpp"
#include "random.hpp"
#include "raster_compare.hpp"
#include "src/scanline_fill.hpp"

namespace {

using scantrace::Color;
using scantrace::FillOptions;
using scantrace::FillRule;
using scantrace::RgbImage;
using scantrace::Shading;
using scantrace::Vec2;
using sttest::Rng;
using Triangle = std::array<Vec2, 3>;
using Colors = std::array<Color, 3>;

constexpr std::array<FillOptions, 4> kModes{{{Shading::flat, FillRule::top_left},
                                             {Shading::gouraud, FillRule::top_left},
                                             {Shading::flat, FillRule::closed},
                                             {Shading::gouraud, FillRule::closed}}};

// v rounded to a multiple of 2^-16: fractional, and still exact after adding whole pixels.
double dyadic(double v) {
  return std::ldexp(std::round(std::ldexp(v, 16)), -16);
}

// A random triangle of one of three kinds: integer vertices (ties everywhere), fractional ones
// (multiples of 2^-16) anywhere in [lo, hi]², and small fractional ones.
Triangle random_triangle(Rng& r, double lo, double hi) {
  Triangle t;
  const long long kind = r.integer(0, 2);
  const Vec2 c = r.point(lo, hi, lo, hi);
  for (Vec2& p : t) {
    if (kind == 0) p = {std::round(r.uniform(lo, hi)), std::round(r.uniform(lo, hi))};
    if (kind == 1) p = {dyadic(r.uniform(lo, hi)), dyadic(r.uniform(lo, hi))};
    if (kind == 2) p = {dyadic(c.x + r.uniform(-2, 2)), dyadic(c.y + r.uniform(-2, 2))};
  }
  return t;
}

RgbImage render(const Triangle& t, const Colors& c, const FillOptions& opt, int w, int h) {
  RgbImage img(w, h, sttest::kSentinel);
  scantrace::fill_triangle(img, t, c, opt);
  return img;
}

using ExactCanvas = sttest::DoubleCanvas;

ExactCanvas render_exact(const Triangle& t, const Colors& c, const FillOptions& opt, int w, int h) {
  ExactCanvas canvas(w, h);
  scantrace::FillScratch scratch;
  scantrace::fill_polygon(canvas, scantrace::PolygonInput{t, c, 0, {}}, opt, scratch);
  return canvas;
}

}  // namespace

// The edge table (exact) and the half-space fill: both are exact, and both must give one image
// however the vertices are listed. The colours are compared as the fill computed them, in double
// (render_exact): a last-bit difference that a float32 image would round away most of the time
// still fails here (the half-space fill summed its barycentric colour in vertex order until a
// 600 s stress run caught one such bit after the float32 store).
TEST_CASE("all six vertex orders give bit-identical results", "[invariance]") {
  const scantrace::Method method = GENERATE(scantrace::Method::exact, scantrace::Method::halfspace);
  Rng rng(0x4001);
  int failures = 0;  // stop after a few: one broken case fails hundreds of comparisons
  for (int i = 0; i < 400 && failures < 3; ++i) {
    const Triangle t = random_triangle(rng, -4, 44);
    const Colors c{rng.color(), rng.color(), rng.color()};
    for (FillOptions opt : kModes) {
      opt.method = method;
      const RgbImage base = render(t, c, opt, 40, 40);
      const ExactCanvas exact = render_exact(t, c, opt, 40, 40);
      std::array<int, 3> perm{0, 1, 2};
      while (std::next_permutation(perm.begin(), perm.end())) {
        const Triangle pt{t[perm[0]], t[perm[1]], t[perm[2]]};
        const Colors pc{c[perm[0]], c[perm[1]], c[perm[2]]};
        INFO("triangle " << sttest::format_points(t) << "order " << perm[0] << perm[1] << perm[2]
                         << ", " << scantrace::to_string(opt.shading) << ", "
                         << scantrace::to_string(opt.fill_rule) << ", "
                         << scantrace::to_string(opt.method));
        const bool same_image = render(pt, pc, opt, 40, 40) == base;
        const bool same_colors = render_exact(pt, pc, opt, 40, 40) == exact;
        CHECK(same_image);
        CHECK(same_colors);
        failures += !same_image || !same_colors;
      }
    }
  }
}

namespace {

// `moved` must be `base` shifted by (dx, dy): same coverage, flat colours bit-identical. Gouraud
// colours are computed from the translated coordinates in floating point and may differ in the
// last bits; each is within 1e-9 of the exact value before the float store
// (test_reference_agreement), so two renders agree within twice that plus the store's rounding.
void check_translated(const RgbImage& base, const RgbImage& moved, int dx, int dy, bool gouraud) {
  long long covered_base = 0, covered_moved = 0, wrong = 0;
  for (int y = 0; y < moved.height(); ++y)
    for (int x = 0; x < moved.width(); ++x) covered_moved += !(moved(x, y) == sttest::kSentinel);
  for (int y = 0; y < base.height() && wrong < 3; ++y)
    for (int x = 0; x < base.width() && wrong < 3; ++x) {
      const scantrace::Rgb32f p = base(x, y);
      if (p == sttest::kSentinel) continue;
      ++covered_base;
      const int mx = x + dx, my = y + dy;
      REQUIRE((mx >= 0 && mx < moved.width() && my >= 0 && my < moved.height()));
      const scantrace::Rgb32f q = moved(mx, my);
      const bool same =
          gouraud ? !(q == sttest::kSentinel) && sttest::near(q, p.color(), 2e-9) : q == p;
      if (same) continue;
      ++wrong;
      INFO("pixel (" << x << ", " << y << ") moved to (" << mx << ", " << my << ")");
      CHECK(sttest::format_color(q.color()) == sttest::format_color(p.color()));
    }
  CHECK(wrong == 0);
  CHECK(covered_moved == covered_base);
}

}  // namespace

namespace {

// Fills t and t moved by (dx, dy) on size × size canvases in every mode and compares.
void check_shift(const Triangle& t, const Colors& c, int dx, int dy, int size) {
  const Triangle moved{Vec2{t[0].x + dx, t[0].y + dy}, Vec2{t[1].x + dx, t[1].y + dy},
                       Vec2{t[2].x + dx, t[2].y + dy}};
  for (const FillOptions& opt : kModes) {
    INFO("triangle " << sttest::format_points(t) << "shift (" << dx << ", " << dy << "), "
                     << scantrace::to_string(opt.shading) << ", "
                     << scantrace::to_string(opt.fill_rule));
    check_translated(render(t, c, opt, size, size), render(moved, c, opt, size, size), dx, dy,
                     opt.shading == Shading::gouraud);
  }
}

}  // namespace

TEST_CASE("translation by whole pixels translates the image", "[invariance]") {
  Rng rng(0x4002);
  SECTION("small shifts on a small canvas") {
    for (int i = 0; i < 400; ++i) {
      const Triangle t = random_triangle(rng, 12, 28);
      const Colors c{rng.color(), rng.color(), rng.color()};
      check_shift(t, c, static_cast<int>(rng.integer(-9, 9)), static_cast<int>(rng.integer(-9, 9)),
                  40);
    }
  }
  SECTION("shifts of hundreds of pixels, in both directions") {
    for (int i = 0; i < 16; ++i) {
      const Triangle t = random_triangle(rng, 310, 390);
      const Colors c{rng.color(), rng.color(), rng.color()};
      check_shift(t, c, std::array{-300, 300, -299, 301}[i % 4],
                  std::array{300, -300, 0, -17}[i / 4], 704);
    }
  }
}
