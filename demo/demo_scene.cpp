#include "demo/demo_scene.hpp"

#include "src/splitmix64.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace scantrace {
namespace {

Color hue(double h) {  // h in [0, 1): fully saturated colour wheel
  const double k = h * 6.0;
  auto ch = [&](double n) {
    const double m = std::fmod(n + k, 6.0);
    return 1.0 - std::max(0.0, std::min({m, 4.0 - m, 1.0}));
  };
  return {ch(5.0), ch(3.0), ch(1.0)};
}

int add_vertex(Scene& s, Vec2 p, Color c, double depth) {
  s.vertices.push_back(p);
  s.vcolors.push_back(c);
  s.depth.push_back(depth);
  return static_cast<int>(s.vertices.size()) - 1;
}

void add_grid(Scene& s, SplitMix64& rng) {
  constexpr int kN = 14;  // vertices per side: 2·13·13 = 338 triangles
  constexpr double kX0 = 24, kY0 = 120, kStep = 26;
  const int base = static_cast<int>(s.vertices.size());
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      // Jitter inside ±30 % of a cell keeps every quad convex; the border stays straight.
      const bool border_x = i == 0 || i == kN - 1, border_y = j == 0 || j == kN - 1;
      const double jx = border_x ? 0 : rng.uniform(-0.3, 0.3) * kStep;
      const double jy = border_y ? 0 : rng.uniform(-0.3, 0.3) * kStep;
      const double u = static_cast<double>(i) / (kN - 1), v = static_cast<double>(j) / (kN - 1);
      const Color c = hue(0.85 * u) * (1.0 - 0.45 * v) + Color{0.45, 0.45, 0.45} * v;
      add_vertex(s, {kX0 + i * kStep + jx, kY0 + j * kStep + jy}, c, 100.0 + 10.0 * v);
    }
  for (int j = 0; j + 1 < kN; ++j)
    for (int i = 0; i + 1 < kN; ++i) {
      const int a = base + j * kN + i, b = a + 1, c = a + kN, d = c + 1;
      if (rng.next() & 1) {
        s.faces.push_back({a, b, d});
        s.faces.push_back({a, d, c});
      } else {
        s.faces.push_back({a, b, c});
        s.faces.push_back({b, d, c});
      }
    }
}

void add_sun(Scene& s) {
  constexpr int kRays = 96;
  constexpr Vec2 kCentre{398, 112};
  const int centre = add_vertex(s, kCentre, {1.0, 0.97, 0.55}, 5.0);
  int first = -1, prev = -1;
  for (int k = 0; k < kRays; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kRays;
    const double radius = (k % 2 == 0) ? 92.0 : 70.0;
    const Color rim = (k % 2 == 0) ? Color{1.0, 0.35, 0.05} : Color{0.95, 0.65, 0.1};
    const int v = add_vertex(
        s, {kCentre.x + radius * std::cos(a), kCentre.y + radius * std::sin(a)}, rim, 5.0);
    if (prev >= 0) s.faces.push_back({centre, prev, v});
    if (first < 0) first = v;
    prev = v;
  }
  s.faces.push_back({centre, prev, first});
}

void add_big_triangles(Scene& s) {
  struct Tri {
    Vec2 a, b, c;
    double depth;
  };
  const Tri tris[] = {{{40, 20}, {300, 60}, {150, 300}, 50.0},
                      {{200, 30}, {480, 250}, {260, 330}, 40.0},
                      {{90, 380}, {470, 300}, {330, 500}, 30.0}};
  const Color rgb[] = {{0.9, 0.1, 0.15}, {0.1, 0.8, 0.2}, {0.15, 0.25, 0.95}};
  for (const Tri& t : tris) {
    const int a = add_vertex(s, t.a, rgb[0], t.depth);
    const int b = add_vertex(s, t.b, rgb[1], t.depth);
    const int c = add_vertex(s, t.c, rgb[2], t.depth);
    s.faces.push_back({a, b, c});
  }
}

}  // namespace

Scene demo_scene() {
  Scene s;
  SplitMix64 rng{20241121};
  add_grid(s, rng);
  add_big_triangles(s);
  add_sun(s);
  return s;
}

}  // namespace scantrace
