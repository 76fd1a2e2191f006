// Hand-derived pixel sets for the situations the fill rule exists for (horizontal and vertical
// edges, shared diagonals), plus degenerate, off-canvas, huge and invalid input.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "raster_compare.hpp"
#include "reference_raster.hpp"
#include "src/scanline_fill.hpp"

namespace {

using scantrace::Color;
using scantrace::FillOptions;
using scantrace::FillResult;
using scantrace::FillRule;
using scantrace::RgbImage;
using scantrace::Shading;
using scantrace::SkipReason;
using scantrace::Vec2;
using Triangle = std::array<Vec2, 3>;

constexpr std::array<Color, 3> kRgb{Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
constexpr FillOptions kTopLeft{Shading::flat, FillRule::top_left};
constexpr FillOptions kClosed{Shading::flat, FillRule::closed};

// "(x,y)": pixel lists in this form are readable values for Catch to compare and print.
std::string name(int x, int y) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "(%d,%d)", x, y);
  return buf;
}

// The written pixels, in row-major order.
std::vector<std::string> written(const RgbImage& img) {
  std::vector<std::string> out;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x)
      if (!(img(x, y) == sttest::kSentinel)) out.push_back(name(x, y));
  return out;
}

// Pixels (x, y) with pred(x, y) true, in the same format and order.
template <class Pred>
std::vector<std::string> where(int width, int height, Pred pred) {
  std::vector<std::string> out;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (pred(x, y)) out.push_back(name(x, y));
  return out;
}

std::vector<std::string> fill(const Triangle& t, const FillOptions& opt, int size = 8) {
  RgbImage img(size, size, sttest::kSentinel);
  scantrace::fill_triangle(img, t, kRgb, opt);
  return written(img);
}

// Coverage and colours against the reference on a width × height canvas, both rules and shadings.
void check_against_reference(const Triangle& t, int width, int height, int bits = 8) {
  for (const FillRule rule : {FillRule::top_left, FillRule::closed}) {
    const sttest::RefRaster ref = sttest::ref_rasterize(
        width, height, t, kRgb,
        rule == FillRule::closed ? sttest::RefRule::closed : sttest::RefRule::top_left, bits);
    for (const Shading shading : {Shading::flat, Shading::gouraud}) {
      RgbImage img(width, height, sttest::kSentinel);
      const FillResult res = scantrace::fill_triangle(img, t, kRgb, {shading, rule, bits});
      const Color flat = sttest::mean_color(kRgb);
      const bool gouraud = shading == Shading::gouraud;
      INFO("triangle " << sttest::format_points(t) << "rule " << scantrace::to_string(rule)
                       << ", shading " << scantrace::to_string(shading));
      CHECK(sttest::first_difference(
                img, ref, [&](int x, int y) { return gouraud ? ref.color_at(x, y) : flat; },
                1e-9) == "");  // exact method: ~1e-12 before the float store
      CHECK(res.pixels == ref.count);
      CHECK(res.rows <= height);
    }
  }
}

// Nothing written, and the reason given.
void check_skipped(const Triangle& t, const FillOptions& opt, SkipReason reason, int size = 32) {
  RgbImage img(size, size, sttest::kSentinel);
  const FillResult res = scantrace::fill_triangle(img, t, kRgb, opt);
  INFO("triangle " << sttest::format_points(t) << "rule " << scantrace::to_string(opt.fill_rule));
  CHECK(res.skipped == reason);
  CHECK(res.pixels == 0);
  CHECK(res.rows == 0);
  CHECK(img == RgbImage(size, size, sttest::kSentinel));
}

}  // namespace

// (0,0),(4,0),(0,4): interior x > 0, y > 0, x + y < 4. The top edge y = 0 (interior below) and the
// left edge x = 0 own their centres, the diagonal (a right edge) does not: x, y >= 0, x + y <= 3.
TEST_CASE("horizontal top edge and vertical left edge are inclusive", "[edge]") {
  const Triangle t{Vec2{0, 0}, Vec2{4, 0}, Vec2{0, 4}};
  CHECK(fill(t, kTopLeft) == where(8, 8, [](int x, int y) { return x + y <= 3; }));
  CHECK(fill(t, kTopLeft).size() == 10);
  // Closed: the diagonal's centres too.
  CHECK(fill(t, kClosed) == where(8, 8, [](int x, int y) { return x + y <= 4; }));
}

// (0,0),(0,4),(4,4): interior x > 0, y < 4, y > x. The bottom edge y = 4 (interior above) is not a
// top edge and the diagonal is a right edge: rows 1..3, columns 0..y-1.
TEST_CASE("horizontal bottom edge is exclusive", "[edge]") {
  const Triangle t{Vec2{0, 0}, Vec2{0, 4}, Vec2{4, 4}};
  CHECK(fill(t, kTopLeft) ==
        std::vector<std::string>{"(0,1)", "(0,2)", "(1,2)", "(0,3)", "(1,3)", "(2,3)"});
  CHECK(fill(t, kClosed) == where(8, 8, [](int x, int y) { return x >= 0 && y <= 4 && x <= y; }));
}

// (0,0),(4,0),(4,4): interior y > 0, x < 4, y < x. The vertical right edge x = 4 is exclusive, the
// diagonal (interior to its right) is a left edge and inclusive, the top edge inclusive.
TEST_CASE("vertical right edge is exclusive, a diagonal left edge inclusive", "[edge]") {
  const Triangle t{Vec2{0, 0}, Vec2{4, 0}, Vec2{4, 4}};
  CHECK(fill(t, kTopLeft) == where(8, 8, [](int x, int y) { return y <= x && x < 4; }));
  CHECK(fill(t, kTopLeft).size() == 10);
  CHECK(fill(t, kClosed) == where(8, 8, [](int x, int y) { return y <= x && x <= 4; }));
}

// (4,0),(4,4),(0,4): interior x < 4, y < 4, x + y > 4; the diagonal is a left edge here.
TEST_CASE("diagonal as a left edge with exclusive right and bottom edges", "[edge]") {
  const Triangle t{Vec2{4, 0}, Vec2{4, 4}, Vec2{0, 4}};
  CHECK(fill(t, kTopLeft) ==
        where(8, 8, [](int x, int y) { return x < 4 && y < 4 && x + y >= 4; }));
  CHECK(fill(t, kTopLeft).size() == 6);
}

// The two triangles above share the diagonal and tile [0,4]²: 16 pixels, each once.
TEST_CASE("two triangles sharing a diagonal tile the square exactly once", "[edge]") {
  RgbImage a(8, 8, sttest::kSentinel), b(8, 8, sttest::kSentinel);
  scantrace::fill_triangle(a, {Vec2{0, 0}, Vec2{4, 0}, Vec2{0, 4}}, kRgb, kTopLeft);
  scantrace::fill_triangle(b, {Vec2{4, 0}, Vec2{4, 4}, Vec2{0, 4}}, kRgb, kTopLeft);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const int n = !(a(x, y) == sttest::kSentinel) + !(b(x, y) == sttest::kSentinel);
      INFO("pixel (" << x << ", " << y << ")");
      CHECK(n == (x < 4 && y < 4 ? 1 : 0));
    }
}

// An arrow pointing right, (1,1),(1,5),(3,3): vertical left edge x = 1, right edges y = x and
// x + y = 6. Top-left: the left edge's centres belong to the triangle except at the two vertices,
// where a right edge also passes; the right vertex (3,3) lies on two right edges.
TEST_CASE("vertical left edge through pixel centres", "[edge]") {
  const Triangle t{Vec2{1, 1}, Vec2{1, 5}, Vec2{3, 3}};
  CHECK(fill(t, kTopLeft) == std::vector<std::string>{"(1,2)", "(1,3)", "(2,3)", "(1,4)"});
  CHECK(fill(t, kClosed) == std::vector<std::string>{"(1,1)", "(1,2)", "(2,2)", "(1,3)", "(2,3)",
                                                     "(3,3)", "(1,4)", "(2,4)", "(1,5)"});
}

// A vertex exactly on a centre: the top apex of a "Λ" sits on two edges, one left and one right.
TEST_CASE("apex vertices on pixel centres", "[edge]") {
  // (2,0),(4,2),(0,2): the apex (2,0) is excluded (on the right edge), the bottom edge y = 2 too.
  CHECK(fill(Triangle{Vec2{2, 0}, Vec2{4, 2}, Vec2{0, 2}}, kTopLeft) ==
        std::vector<std::string>{"(1,1)", "(2,1)"});
  // The same shape upside down: (0,0),(4,0),(2,2): the top edge is inclusive, the apex excluded.
  CHECK(fill(Triangle{Vec2{0, 0}, Vec2{4, 0}, Vec2{2, 2}}, kTopLeft) ==
        std::vector<std::string>{"(0,0)", "(1,0)", "(2,0)", "(3,0)", "(1,1)", "(2,1)"});
}

TEST_CASE("coincident vertices fill nothing", "[edge][degenerate]") {
  for (const FillOptions& opt : {kTopLeft, kClosed}) {
    check_skipped({Vec2{3, 3}, Vec2{3, 3}, Vec2{3, 3}}, opt, SkipReason::degenerate);
    check_skipped({Vec2{1, 1}, Vec2{1, 1}, Vec2{5, 2}}, opt, SkipReason::degenerate);
    check_skipped({Vec2{2.5, 7.25}, Vec2{9, 1}, Vec2{2.5, 7.25}}, opt, SkipReason::degenerate);
    // Distinct inputs that snap to one grid point (1/256 px).
    check_skipped({Vec2{4, 4}, Vec2{4.001, 4}, Vec2{4, 4.001}}, opt, SkipReason::degenerate);
  }
}

// Collinear vertices: a line through pixel centres. A naive closed fill would paint the centres on
// it; a zero-area triangle owns no pixel under either rule.
TEST_CASE("collinear vertices fill nothing", "[edge][degenerate]") {
  for (const FillOptions& opt : {kTopLeft, kClosed}) {
    check_skipped({Vec2{0, 0}, Vec2{2, 2}, Vec2{5, 5}}, opt, SkipReason::degenerate);
    check_skipped({Vec2{0, 2}, Vec2{3, 2}, Vec2{7, 2}}, opt, SkipReason::degenerate);
    check_skipped({Vec2{1, 1}, Vec2{1, 6}, Vec2{1, 4}}, opt, SkipReason::degenerate);
    check_skipped({Vec2{1, 9}, Vec2{4, 3}, Vec2{7, -3}}, opt, SkipReason::degenerate);
    // Collinear only after snapping: 2.0001 px is 512.0256 grid units, rounded to 512.
    check_skipped({Vec2{0, 0}, Vec2{1, 1}, Vec2{2, 2.0001}}, opt, SkipReason::degenerate);
  }
  // ...whereas 2.003 px snaps to 513 units: a real (if thin) triangle, not skipped.
  RgbImage img(8, 8, sttest::kSentinel);
  const FillResult res =
      scantrace::fill_triangle(img, {Vec2{0, 0}, Vec2{1, 1}, Vec2{2, 2.003}}, kRgb, kClosed);
  CHECK(res.skipped == SkipReason::none);
}

TEST_CASE("slivers thinner than a pixel agree with the reference", "[edge][sliver]") {
  // Hugging a diagonal through centres from either side, and straddling it.
  check_against_reference({Vec2{0, 0}, Vec2{20, 20}, Vec2{20, 20.01}}, 24, 24);
  check_against_reference({Vec2{0, 0}, Vec2{20, 20}, Vec2{20.01, 20}}, 24, 24);
  check_against_reference({Vec2{0, -0.004}, Vec2{20, 19.996}, Vec2{0, 0.004}}, 24, 24);
  // Nearly horizontal and nearly vertical, along a row / column of centres.
  check_against_reference({Vec2{-3, 5}, Vec2{30, 5}, Vec2{30, 5.02}}, 24, 24);
  check_against_reference({Vec2{-3, 5}, Vec2{30, 4.98}, Vec2{30, 5}}, 24, 24);
  check_against_reference({Vec2{7, -2}, Vec2{7.02, 30}, Vec2{7, 30}}, 24, 24);
  check_against_reference({Vec2{7, -2}, Vec2{6.99, 30}, Vec2{7, 30}}, 24, 24);
  // Long, shallow and between rows almost everywhere.
  check_against_reference({Vec2{0.5, 0.3}, Vec2{60.5, 40.1}, Vec2{60.5, 40.11}}, 64, 48);
  check_against_reference({Vec2{1.1, 40.2}, Vec2{63.3, 1.7}, Vec2{63.3, 1.74}}, 64, 48);
}

TEST_CASE("triangles wholly off the canvas are skipped without writing", "[edge][offscreen]") {
  for (const FillOptions& opt : {kTopLeft, kClosed}) {
    check_skipped({Vec2{-10, -10}, Vec2{-5, -10}, Vec2{-7, -3}}, opt, SkipReason::offscreen);
    check_skipped({Vec2{-10, 5}, Vec2{-0.5, 8}, Vec2{-4, 30}}, opt, SkipReason::offscreen);
    check_skipped({Vec2{32, 0}, Vec2{40, 0}, Vec2{36, 5}}, opt, SkipReason::offscreen);
    check_skipped({Vec2{5, 31.5}, Vec2{40, 33}, Vec2{0, 80}}, opt, SkipReason::offscreen);
    check_skipped({Vec2{5, -0.5}, Vec2{40, -3}, Vec2{0, -80}}, opt, SkipReason::offscreen);
    check_skipped({Vec2{1e6, 1e6}, Vec2{2e6, 1e6}, Vec2{1e6, 3e6}}, opt, SkipReason::offscreen);
  }
}

// (-4,0),(0,0),(0,4) touches the canvas only with its right edge x = 0, on the centres of column 0:
// outside under top-left (right edges are exclusive), five pixels under the closed rule.
TEST_CASE("a triangle touching the canvas with its right edge", "[edge][offscreen]") {
  const Triangle t{Vec2{-4, 0}, Vec2{0, 0}, Vec2{0, 4}};
  check_skipped(t, kTopLeft, SkipReason::offscreen);
  CHECK(fill(t, kClosed) == std::vector<std::string>{"(0,0)", "(0,1)", "(0,2)", "(0,3)", "(0,4)"});
}

// A triangle on the canvas whose bounding box holds no pixel centre — columns ceil(1.1) = 2 …
// ceil(1.6) − 1 = 1 — cannot own a pixel; it is skipped for that reason, not as "offscreen". The
// closed rule needs a centre on the boundary: 1.1…1.6 still contains none.
TEST_CASE("a triangle between pixel centres is skipped as having none", "[edge][subpixel]") {
  const Triangle t{Vec2{1.1, 1.1}, Vec2{1.6, 1.2}, Vec2{1.3, 1.8}};
  check_skipped(t, kTopLeft, SkipReason::no_pixel_centre);
  check_skipped(t, kClosed, SkipReason::no_pixel_centre);
  // Between rows only (columns 1 … 4 are spanned, no row centre in 2.2 … 2.9).
  check_skipped({Vec2{0.5, 2.2}, Vec2{4.5, 2.4}, Vec2{2, 2.9}}, kTopLeft,
                SkipReason::no_pixel_centre);
}

// A vertex a billion pixels away: the visible part must be exact, and the rows visited are the
// canvas rows at most (rows outside the canvas are never iterated).
TEST_CASE("vertices far outside the canvas give the exact visible result", "[edge][huge]") {
  check_against_reference({Vec2{100, 50}, Vec2{400, 300}, Vec2{1e9, 1e9}}, 512, 512);
  check_against_reference({Vec2{-1e9, 300}, Vec2{200, 100}, Vec2{300, 450}}, 512, 512);
  check_against_reference({Vec2{-1e9, -1e9}, Vec2{511.5, 3}, Vec2{20.25, 1e9}}, 512, 512);
  check_against_reference({Vec2{-1e9, 1e9}, Vec2{1e9, 1e9 + 7}, Vec2{256, 255.5}}, 512, 512);
  // The largest supported coordinates at the finest grid: 2^30 px at 2^12 units per pixel.
  const double m = std::ldexp(1.0, 30);
  check_against_reference({Vec2{-m, -m}, Vec2{m, 5}, Vec2{3, m}}, 64, 64, 12);
  check_against_reference({Vec2{-m, 10}, Vec2{m, 10.5}, Vec2{30, 11}}, 64, 64, 12);
}

// Rows visited are counted on the canvas only: (100,50),(400,300),(1e9,1e9) spans rows 50 and
// down, far past the last canvas row 511.
TEST_CASE("only canvas rows are visited", "[edge][huge]") {
  RgbImage img(512, 512, sttest::kSentinel);
  const Triangle t{Vec2{100, 50}, Vec2{400, 300}, Vec2{1e9, 1e9}};
  CHECK(scantrace::fill_triangle(img, t, kRgb, kTopLeft).rows == 511 - 50 + 1);
  const Triangle above{Vec2{-1e9, -1e9}, Vec2{300, 20.5}, Vec2{10, 99.5}};
  CHECK(scantrace::fill_triangle(img, above, kRgb, kTopLeft).rows == 99 - 0 + 1);
}

TEST_CASE("a triangle around the whole canvas fills every pixel once", "[edge][huge]") {
  RgbImage img(512, 512, sttest::kSentinel);
  const FillResult res = scantrace::fill_triangle(
      img, {Vec2{-1e9, -1e9}, Vec2{1e9, -1e9}, Vec2{0, 1e9}}, kRgb, kTopLeft);
  CHECK(res.skipped == SkipReason::none);
  CHECK(res.rows == 512);
  CHECK(res.pixels == 512 * 512);
  CHECK(written(img).size() == 512u * 512u);
}

TEST_CASE("non-finite or out-of-range coordinates are rejected", "[edge][range]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const double over = std::ldexp(1.0, 30) + 1;
  for (const FillOptions& opt : {kTopLeft, kClosed})
    for (const double bad : {nan, inf, -inf, over, -over, 1e300})
      for (int vertex = 0; vertex < 3; ++vertex)
        for (int axis = 0; axis < 2; ++axis) {
          Triangle t{Vec2{1, 1}, Vec2{20, 2}, Vec2{5, 25}};
          (axis == 0 ? t[vertex].x : t[vertex].y) = bad;
          check_skipped(t, opt, SkipReason::out_of_range);
        }
  // The limit itself is supported.
  RgbImage img(32, 32, sttest::kSentinel);
  const double m = std::ldexp(1.0, 30);
  const FillResult res =
      scantrace::fill_triangle(img, {Vec2{1, 1}, Vec2{m, 2}, Vec2{-m, m}}, kRgb, kTopLeft);
  CHECK(res.skipped == SkipReason::none);
}

TEST_CASE("fewer than three vertices are skipped, malformed input is refused", "[edge]") {
  RgbImage img(8, 8, sttest::kSentinel);
  const std::array<Vec2, 2> two{Vec2{0, 0}, Vec2{5, 5}};
  const std::array<Vec2, 3> three{Vec2{0, 0}, Vec2{5, 0}, Vec2{0, 5}};
  const std::span<const Color> colors(kRgb);
  CHECK(scantrace::fill_convex_polygon(img, std::span<const Vec2>(two), colors.first(2)).skipped ==
        SkipReason::too_few_vertices);
  // Programming errors rather than data: a colour missing, a grid finer than the arithmetic
  // supports (it would overflow) or a negative one.
  CHECK_THROWS_AS(
      scantrace::fill_convex_polygon(img, std::span<const Vec2>(three), colors.first(2)),
      std::invalid_argument);
  for (const int bits : {-1, scantrace::kMaxSubpixelBits + 1, 62})
    CHECK_THROWS_AS(
        scantrace::fill_convex_polygon(img, std::span<const Vec2>(three), colors,
                                       FillOptions{Shading::flat, FillRule::top_left, bits}),
        std::invalid_argument);
  CHECK(img == RgbImage(8, 8, sttest::kSentinel));
}
