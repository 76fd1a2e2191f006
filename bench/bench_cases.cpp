#include "bench/bench_cases.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "src/splitmix64.hpp"

namespace scantrace::bench {
namespace {

Scene canvas(int width, int height) {
  Scene s;
  s.width = width;
  s.height = height;
  s.background = {1, 1, 1};
  return s;
}

void add_face(Scene& s, const std::array<Vec2, 3>& v, const std::array<Color, 3>& c, double depth) {
  const int base = static_cast<int>(s.vertices.size());
  for (int k = 0; k < 3; ++k) {
    s.vertices.push_back(v[k]);
    s.vcolors.push_back(c[k]);
    s.depth.push_back(depth);
  }
  s.faces.push_back({base, base + 1, base + 2});
}

Color random_color(SplitMix64& rng) {
  return {rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)};
}

// Sutherland–Hodgman clipping of a polygon to the half-plane a·x + b·y <= c.
std::vector<Vec2> clip(const std::vector<Vec2>& poly, double a, double b, double c) {
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 p = poly[i], q = poly[(i + 1) % poly.size()];
    const double dp = a * p.x + b * p.y - c, dq = a * q.x + b * q.y - c;
    if (dp <= 0) out.push_back(p);
    if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) {
      const double t = dp / (dp - dq);
      out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    }
  }
  return out;
}

constexpr std::array<Vec2, 3> kFarTriangle{Vec2{-1e9, 250.5}, Vec2{500.25, 10.75},
                                           Vec2{430.5, 505.25}};
constexpr std::array<Color, 3> kFarColors{Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};

}  // namespace

Scene small_triangles(std::uint64_t seed, int width, int height, int count, double mean_area) {
  SplitMix64 rng(seed);
  Scene s = canvas(width, height);
  const double side = std::sqrt(mean_area * 144.0 / 11.0);
  for (int f = 0; f < count; ++f) {
    const Vec2 centre{rng.uniform(0, width), rng.uniform(0, height)};
    std::array<Vec2, 3> v;
    for (Vec2& p : v)
      p = {centre.x + rng.uniform(-side / 2, side / 2),
           centre.y + rng.uniform(-side / 2, side / 2)};
    add_face(s, v, {random_color(rng), random_color(rng), random_color(rng)}, rng.uniform(0, 1));
  }
  return s;
}

Scene half_canvas_triangle(int size) {
  Scene s = canvas(size, size);
  const double n = size;
  add_face(s, {Vec2{0, 0}, Vec2{n, 0}, Vec2{0, n}},
           {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}}, 0);
  return s;
}

Scene far_vertex_triangle() {
  Scene s = canvas(512, 512);
  add_face(s, kFarTriangle, kFarColors, 0);
  return s;
}

Scene far_vertex_visible_part() {
  std::vector<Vec2> poly(kFarTriangle.begin(), kFarTriangle.end());
  // The canvas's pixel centres span [0, 511]; clipping half a pixel outside keeps every centre.
  poly = clip(poly, -1, 0, 0.5);
  poly = clip(poly, 1, 0, 511.5);
  poly = clip(poly, 0, -1, 0.5);
  poly = clip(poly, 0, 1, 511.5);
  Scene s = canvas(512, 512);
  for (std::size_t i = 1; i + 1 < poly.size(); ++i)
    add_face(s, {poly[0], poly[i], poly[i + 1]}, kFarColors, 0);
  return s;
}

namespace {

// The corners of a width × height canvas cut into cells_x × cells_y cells, row by row, the inner
// ones moved at random by up to 0.3 of a cell (the border stays on the canvas's edges).
std::vector<Vec2> jittered_grid(SplitMix64& rng, int width, int height, int cells_x, int cells_y) {
  const double w = static_cast<double>(width) / cells_x, h = static_cast<double>(height) / cells_y;
  std::vector<Vec2> grid;
  for (int j = 0; j <= cells_y; ++j)
    for (int i = 0; i <= cells_x; ++i) {
      const bool inner = i > 0 && j > 0 && i < cells_x && j < cells_y;
      grid.push_back({i * w + (inner ? rng.uniform(-0.3, 0.3) * w : 0),
                      j * h + (inner ? rng.uniform(-0.3, 0.3) * h : 0)});
    }
  return grid;
}

}  // namespace

Scene grid_mesh(std::uint64_t seed, int width, int height, int cells_x, int cells_y) {
  SplitMix64 rng(seed);
  Scene s = canvas(width, height);
  const std::vector<Vec2> grid = jittered_grid(rng, width, height, cells_x, cells_y);
  const auto at = [&](int i, int j) {
    return grid[static_cast<std::size_t>(j) * (cells_x + 1) + i];
  };
  for (int j = 0; j < cells_y; ++j)
    for (int i = 0; i < cells_x; ++i) {
      add_face(s, {at(i, j), at(i + 1, j), at(i + 1, j + 1)},
               {random_color(rng), random_color(rng), random_color(rng)}, rng.uniform(0, 1));
      add_face(s, {at(i, j), at(i + 1, j + 1), at(i, j + 1)},
               {random_color(rng), random_color(rng), random_color(rng)}, rng.uniform(0, 1));
    }
  return s;
}

Scene surface_layers(std::uint64_t seed, int width, int height, int cells_x, int cells_y,
                     int layers) {
  SplitMix64 rng(seed);
  Scene s = canvas(width, height);
  const int row = cells_x + 1;
  for (int k = 0; k < layers; ++k) {
    const int first = static_cast<int>(s.vertices.size());
    for (const Vec2 corner : jittered_grid(rng, width, height, cells_x, cells_y)) {
      s.vertices.push_back(corner);
      s.vcolors.push_back(random_color(rng));
      s.depth.push_back(k + rng.uniform(0, 1));
    }
    for (int j = 0; j < cells_y; ++j)
      for (int i = 0; i < cells_x; ++i) {
        const int a = first + j * row + i;
        s.faces.push_back({a, a + 1, a + row + 1});
        s.faces.push_back({a, a + row + 1, a + row});
      }
  }
  return s;
}

Scene offscreen_triangles(int count) {
  Scene s = canvas(512, 512);
  for (int f = 0; f < count; ++f) {
    const double y = f % 512;
    add_face(s, {Vec2{-40, y}, Vec2{-10, y + 7}, Vec2{-25, y + 20}},
             {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}}, 0);
  }
  return s;
}

Scene zero_area_triangles(int count) {
  Scene s = canvas(512, 512);
  for (int f = 0; f < count; ++f) {
    const double y = f % 512;
    add_face(s, {Vec2{10, y}, Vec2{200, y + 50}, Vec2{390, y + 100}},
             {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}}, 0);
  }
  return s;
}

Scene uniform_colour_triangles(std::uint64_t seed, int count) {
  Scene s = small_triangles(seed, 512, 512, count, 70);
  for (std::size_t v = 0; v < s.vcolors.size(); v += 3)
    s.vcolors[v + 1] = s.vcolors[v + 2] = s.vcolors[v];
  return s;
}

}  // namespace scantrace::bench
