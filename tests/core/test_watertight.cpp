// Watertightness on the real fill: triangulations of a rectangle, filled through a canvas that
// counts writes, must cover every pixel of the rectangle exactly once under the top-left rule. The
// expected set is computed from the rectangle alone, not from any triangle.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <vector>

#include "counting_canvas.hpp"
#include "random.hpp"
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

struct Rect {
  double x0, y0, x1, y1;
};

double cross(Vec2 a, Vec2 b, Vec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// A jittered nx × ny grid over the rectangle, each cell split along a random diagonal. Vertices on
// the rectangle's sides move only along them, corners not at all; jitter up to a fifth of a cell
// keeps every cell convex, so both diagonals give a valid triangulation.
std::vector<Triangle> grid_mesh(Rng& rng, const Rect& r, int nx, int ny, bool jitter) {
  const double cw = (r.x1 - r.x0) / nx, ch = (r.y1 - r.y0) / ny;
  std::vector<Vec2> v((nx + 1) * (ny + 1));
  auto at = [&](int i, int j) -> Vec2& { return v[j * (nx + 1) + i]; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double jx = jitter ? rng.uniform(-0.2, 0.2) * cw : 0.0;
      const double jy = jitter ? rng.uniform(-0.2, 0.2) * ch : 0.0;
      const double x = i == 0 ? r.x0 : i == nx ? r.x1 : r.x0 + i * cw + jx;
      const double y = j == 0 ? r.y0 : j == ny ? r.y1 : r.y0 + j * ch + jy;
      at(i, j) = {x, y};
    }
  std::vector<Triangle> mesh;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      REQUIRE(cross(a, b, c) > 0);  // convex cell: all four corner triangles positively oriented
      REQUIRE(cross(a, c, d) > 0);
      REQUIRE(cross(a, b, d) > 0);
      REQUIRE(cross(b, c, d) > 0);
      if (rng.coin()) {
        mesh.push_back({a, b, c});
        mesh.push_back({a, c, d});
      } else {
        mesh.push_back({a, b, d});
        mesh.push_back({b, c, d});
      }
    }
  return mesh;
}

// A fan around `centre` whose rim runs along the rectangle's boundary through its four corners,
// with `per_side` random rim vertices on each side.
std::vector<Triangle> fan_mesh(Rng& rng, const Rect& r, Vec2 centre, int per_side, bool integer) {
  auto along = [&](double lo, double hi) {
    std::vector<double> t;
    for (int k = 0; k < per_side; ++k) {
      const double u = rng.uniform(lo, hi);
      t.push_back(integer ? std::round(u) : u);
    }
    return t;
  };
  std::vector<Vec2> rim;
  std::vector<double> s = along(r.x0, r.x1);
  std::sort(s.begin(), s.end());
  rim.push_back({r.x0, r.y0});
  for (double x : s) rim.push_back({x, r.y0});  // top, left to right
  s = along(r.y0, r.y1);
  std::sort(s.begin(), s.end());
  rim.push_back({r.x1, r.y0});
  for (double y : s) rim.push_back({r.x1, y});  // right, downwards
  s = along(r.x0, r.x1);
  std::sort(s.rbegin(), s.rend());
  rim.push_back({r.x1, r.y1});
  for (double x : s) rim.push_back({x, r.y1});  // bottom, right to left
  s = along(r.y0, r.y1);
  std::sort(s.rbegin(), s.rend());
  rim.push_back({r.x0, r.y1});
  for (double y : s) rim.push_back({r.x0, y});  // left, upwards
  std::vector<Triangle> mesh;
  for (std::size_t k = 0; k < rim.size(); ++k)
    mesh.push_back({centre, rim[k], rim[(k + 1) % rim.size()]});
  return mesh;
}

void fill_mesh(sttest::CountingCanvas& canvas, const std::vector<Triangle>& mesh,
               const FillOptions& opt, Rng& rng) {
  scantrace::FillScratch scratch;  // shared across the mesh, as a renderer does
  for (std::size_t f = 0; f < mesh.size(); ++f) {
    const std::array<Color, 3> c{rng.color(), rng.color(), rng.color()};
    scantrace::fill_polygon(canvas, scantrace::PolygonInput{mesh[f], c, static_cast<int>(f), {}},
                            opt, scratch);
  }
}

// Under the top-left rule the rectangle owns the centres of [x0, x1) × [y0, y1) (its left and top
// sides are inclusive, right and bottom exclusive), on the snapped corners.
void check_exactly_once(const sttest::CountingCanvas& canvas, const Rect& r) {
  auto first = [](double v) { return sttest::ceil_div(sttest::ref_snap(v, 8), 256); };
  const long long x_begin = first(r.x0), x_end = first(r.x1);
  const long long y_begin = first(r.y0), y_end = first(r.y1);
  CHECK(canvas.out_of_bounds() == 0);
  int wrong = 0;
  for (int y = 0; y < canvas.height() && wrong < 3; ++y)
    for (int x = 0; x < canvas.width() && wrong < 3; ++x) {
      const int expected = x >= x_begin && x < x_end && y >= y_begin && y < y_end ? 1 : 0;
      if (canvas.count(x, y) == expected) continue;
      ++wrong;
      INFO("rectangle (" << r.x0 << ", " << r.y0 << ") - (" << r.x1 << ", " << r.y1 << "), pixel ("
                         << x << ", " << y << ")");
      CHECK(canvas.count(x, y) == expected);
    }
  CHECK(wrong == 0);
}

constexpr FillOptions kFlat{Shading::flat, FillRule::top_left};
constexpr FillOptions kGouraud{Shading::gouraud, FillRule::top_left};

}  // namespace

TEST_CASE("jittered grid triangulations cover a rectangle exactly once", "[watertight]") {
  Rng rng(0x3001);
  sttest::CountingCanvas canvas(96, 80);
  for (int trial = 0; trial < 60; ++trial) {
    // Fractional corners, sometimes reaching past the canvas edges (the expected set is clipped
    // by the loop over canvas pixels).
    const double x0 = rng.uniform(-12, 60), y0 = rng.uniform(-12, 50);
    const Rect r{x0, y0, x0 + rng.uniform(3, 60), y0 + rng.uniform(3, 50)};
    const int nx = static_cast<int>(rng.integer(1, 12)), ny = static_cast<int>(rng.integer(1, 12));
    const std::vector<Triangle> mesh = grid_mesh(rng, r, nx, ny, true);
    for (const FillOptions& opt : {kFlat, kGouraud}) {
      canvas.clear();
      fill_mesh(canvas, mesh, opt, rng);
      check_exactly_once(canvas, r);
    }
  }
}

// Integer corners and an unjittered integer grid: every shared edge runs through pixel centres,
// the hardest case for the tie rule.
TEST_CASE("integer grid triangulations cover a rectangle exactly once", "[watertight]") {
  Rng rng(0x3002);
  sttest::CountingCanvas canvas(64, 64);
  for (int trial = 0; trial < 40; ++trial) {
    const int nx = static_cast<int>(rng.integer(1, 8)), ny = static_cast<int>(rng.integer(1, 8));
    const double x0 = static_cast<double>(rng.integer(-5, 20));
    const double y0 = static_cast<double>(rng.integer(-5, 20));
    const Rect r{x0, y0, x0 + nx * static_cast<double>(rng.integer(1, 6)),
                 y0 + ny * static_cast<double>(rng.integer(1, 6))};
    canvas.clear();
    fill_mesh(canvas, grid_mesh(rng, r, nx, ny, false), kFlat, rng);
    check_exactly_once(canvas, r);
  }
}

TEST_CASE("fans of hundreds of thin triangles cover a rectangle exactly once", "[watertight]") {
  Rng rng(0x3003);
  sttest::CountingCanvas canvas(128, 100);
  for (int trial = 0; trial < 24; ++trial) {
    const bool integer = trial % 2 == 1;
    const double x0 = rng.uniform(-5, 30), y0 = rng.uniform(-5, 25);
    Rect r{x0, y0, x0 + rng.uniform(40, 100), y0 + rng.uniform(30, 75)};
    if (integer) r = {std::round(r.x0), std::round(r.y0), std::round(r.x1), std::round(r.y1)};
    Vec2 centre = rng.point(r.x0 + 1, r.x1 - 1, r.y0 + 1, r.y1 - 1);
    if (integer) centre = {std::round(centre.x), std::round(centre.y)};
    const std::vector<Triangle> mesh = fan_mesh(rng, r, centre, 100, integer);
    REQUIRE(mesh.size() >= 400);
    for (const FillOptions& opt : {kFlat, kGouraud}) {
      canvas.clear();
      fill_mesh(canvas, mesh, opt, rng);
      check_exactly_once(canvas, r);
    }
  }
}

// The closed rule fills every boundary centre of every triangle, so centres on shared edges are
// painted by both neighbours: the reason it is not the default.
TEST_CASE("the closed rule paints shared edges twice", "[watertight]") {
  Rng rng(0x3004);
  const Rect r{2, 3, 42, 35};
  const std::vector<Triangle> mesh = grid_mesh(rng, r, 5, 4, false);
  sttest::CountingCanvas closed(48, 40), top_left(48, 40);
  fill_mesh(closed, mesh, {Shading::flat, FillRule::closed}, rng);
  fill_mesh(top_left, mesh, kFlat, rng);
  int max_count = 0, doubled = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 48; ++x) {
      max_count = std::max(max_count, closed.count(x, y));
      doubled += closed.count(x, y) >= 2;
      // Closed covers a superset of top-left.
      if (top_left.count(x, y) > 0) CHECK(closed.count(x, y) >= 1);
    }
  CHECK(max_count >= 2);
  // Shared edges here: 4 inner vertical lines, 3 inner horizontal ones and 20 diagonals, all
  // through centres; far more than a handful of pixels are doubled.
  CHECK(doubled > 100);
}
