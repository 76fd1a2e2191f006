#include "demo/demo_mesh.hpp"

#include <cmath>
#include <numbers>

namespace scantrace {
namespace {

Color hue(double h) {  // h in [0, 1): a smooth, fully saturated colour wheel, softened
  const auto c = [&](double phase) {
    return 0.55 + 0.45 * std::cos(2 * std::numbers::pi * (h - phase));
  };
  return {c(0.0), c(1.0 / 3), c(2.0 / 3)};
}

}  // namespace

Mesh demo_torus(double R, double r, int rings, int sides, double tilt_degrees) {
  Mesh m;
  const double tilt = tilt_degrees * std::numbers::pi / 180;
  const double ct = std::cos(tilt), st = std::sin(tilt);
  for (int i = 0; i < rings; ++i) {
    const double u = 2 * std::numbers::pi * i / rings;
    for (int j = 0; j < sides; ++j) {
      const double v = 2 * std::numbers::pi * j / sides;
      const Vec3 p{(R + r * std::cos(v)) * std::cos(u), r * std::sin(v),
                   (R + r * std::cos(v)) * std::sin(u)};
      // Tilt about x: the ring (in the xz plane) leans towards the viewer.
      m.positions.push_back({p.x, ct * p.y - st * p.z, st * p.y + ct * p.z});
      m.colors.push_back(hue(static_cast<double>(i) / rings));
    }
  }
  const auto at = [&](int i, int j) { return (i % rings) * sides + (j % sides); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      // (u, v) increasing: with u turning from x to z and v from the ring plane outwards-up,
      // this order is counter-clockwise seen from outside the tube.
      const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      m.faces.push_back({a, d, c});
      m.faces.push_back({a, c, b});
    }
  return m;
}

}  // namespace scantrace
