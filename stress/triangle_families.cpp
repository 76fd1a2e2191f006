// The single-triangle families. Each picks its geometry in pixels, then puts every vertex on the
// case's grid (grid.hpp), so the fill's snapping is the identity and the reference and the fill
// decide on the same triangle.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#include "stress/generators.hpp"
#include "stress/grid.hpp"

namespace scantrace::stress::detail {

Color random_color(Rng& rng) {
  const auto channel = [&] {
    if (rng.chance(1, 4)) return rng.coin() ? 1.0 : 0.0;
    return rng.unit();
  };
  const double r = channel(), g = channel(), b = channel();
  return {r, g, b};
}

namespace {

void set_triangle(Rng& rng, StressCase& c, Vec2 a, Vec2 b, Vec2 d) {
  Triangle t;
  t.v = {on_grid(a, c.bits), on_grid(b, c.bits), on_grid(d, c.bits)};
  for (Color& col : t.c) col = random_color(rng);
  c.triangles = {t};
}

Vec2 swap_xy(Vec2 p) {
  return {p.y, p.x};
}

void transpose(StressCase& c) {
  std::swap(c.width, c.height);
  for (Triangle& t : c.triangles)
    for (Vec2& p : t.v) p = swap_xy(p);
}

// x with a·x ≡ g (mod b) and y with a·x + b·y = g = gcd(a, b), for a, b >= 0 (extended Euclid).
std::int64_t ext_gcd(std::int64_t a, std::int64_t b, std::int64_t& x, std::int64_t& y) {
  if (b == 0) {
    x = 1;
    y = 0;
    return a;
  }
  std::int64_t x1 = 0, y1 = 0;
  const std::int64_t g = ext_gcd(b, a % b, x1, y1);
  x = y1;
  y = x1 - (a / b) * y1;
  return g;
}

}  // namespace

void generate_random(Rng& rng, StressCase& c) {
  static constexpr int kBits[] = {0, 2, 4, 8, 8, 12};
  c.bits = kBits[rng.integer(0, 5)];
  c.kind = "bits " + std::to_string(c.bits);
  const double size = rng.scale(0.5, 700);
  const Vec2 centre{rng.uniform(-64, 576), rng.uniform(-64, 576)};
  const auto vertex = [&] {
    return Vec2{centre.x + rng.uniform(-size, size), centre.y + rng.uniform(-size, size)};
  };
  const Vec2 a = vertex(), b = vertex(), d = vertex();
  set_triangle(rng, c, a, b, d);
}

void generate_sliver(Rng& rng, StressCase& c) {
  c.bits = 8;
  const double length = rng.scale(1, 16000);
  const double width = rng.scale(0.01, 0.95);
  Vec2 a, dir;
  if (length <= 400) {
    // Any direction on the usual canvas.
    c.kind = "short";
    a = {rng.uniform(-20, 532), rng.uniform(-20, 532)};
    rng.direction(dir.x, dir.y);
  } else {
    // Long slivers run along a canvas that is long in the same direction and 64 px across, so
    // that the reference's bounding box (and the check's cost) stays proportional to the length.
    c.kind = "long";
    c.width = static_cast<int>(std::min(16384.0, std::ceil(length) + 48));
    c.height = 64;
    a = {rng.uniform(-16, 16), rng.uniform(12, 52)};
    const double rise = rng.uniform(-40, 40) / length;  // at most 40 px across the whole length
    dir = {std::sqrt(1 - rise * rise), rise};
  }
  const Vec2 b{a.x + length * dir.x, a.y + length * dir.y};
  const double t = rng.unit(), side = rng.coin() ? width : -width;
  const Vec2 d{a.x + t * (b.x - a.x) - side * dir.y, a.y + t * (b.y - a.y) + side * dir.x};
  set_triangle(rng, c, a, b, d);
  if (c.kind == "long" && rng.coin()) {
    c.kind = "long, vertical";
    transpose(c);
  }
}

void generate_near_collinear(Rng& rng, StressCase& c) {
  // On the 1/4096 grid twice the area of a triangle is an integer k in units of 4096^-2 px², so
  // the area is chosen exactly: pick the edge AB in grid units, then the third vertex by solving
  // cross(AB, AC) = k (extended Euclid), slid along AB to a random position.
  c.bits = 12;
  const std::int64_t s = std::int64_t{1} << c.bits;
  const std::int64_t ax = rng.integer(0, 512 * s), ay = rng.integer(0, 512 * s);
  double ux = 0, uy = 0;
  rng.direction(ux, uy);
  const double length = rng.scale(4, 700) * static_cast<double>(s);
  const std::int64_t p = std::llround(length * ux), q = std::llround(length * uy);
  std::int64_t x0 = 0, y0 = 0;
  const std::int64_t g = ext_gcd(std::llabs(p), std::llabs(q), x0, y0);  // |p|·x0 + |q|·y0 = g
  // With sign corrections: p·sy + q·sx' = g, i.e. p·wy − q·wx = g for w = (−sx', sy).
  const std::int64_t sy = p < 0 ? -x0 : x0, sxp = q < 0 ? -y0 : y0;
  // Twice the area from 34 units (area 1.01e-6 px²) up to 2^27 units (4 px²), a multiple of g.
  const std::int64_t k_target = static_cast<std::int64_t>(rng.scale(34, 134217728.0));
  const std::int64_t m = std::max<std::int64_t>(1, (k_target + g - 1) / g);
  const std::int64_t wx0 = -sxp * m, wy0 = sy * m;  // cross((p, q), w0) = m·g
  // Slide along AB: w = w0 + j·(p, q) with j nearest to the wanted position t ∈ [−0.3, 1.3].
  const double t = rng.uniform(-0.3, 1.3);
  const double pp = static_cast<double>(p) * static_cast<double>(p) +
                    static_cast<double>(q) * static_cast<double>(q);
  const double along = (static_cast<double>(wx0) * static_cast<double>(p) +
                        static_cast<double>(wy0) * static_cast<double>(q)) /
                       pp;
  const std::int64_t j = std::llround(t - along);
  const std::int64_t wx = wx0 + j * p, wy = wy0 + j * q;
  c.kind = "2A = " + std::to_string(m * g) + "/4096^2";
  const Vec2 a{from_units(ax, c.bits), from_units(ay, c.bits)};
  const Vec2 b{from_units(ax + p, c.bits), from_units(ay + q, c.bits)};
  const Vec2 d{from_units(ax + wx, c.bits), from_units(ay + wy, c.bits)};
  set_triangle(rng, c, a, b, d);
}

void generate_huge(Rng& rng, StressCase& c) {
  // Whole pixels, the default grid and the finest one: at 1e9 px and 12 bits the fill's integers
  // are closest to their limits (fixed_point.hpp).
  static constexpr int kBits[] = {0, 8, 8, 12};
  c.bits = kBits[rng.integer(0, 3)];
  const int far_count = static_cast<int>(c.index % 3) + 1;
  c.kind = std::to_string(far_count) + " far, bits " + std::to_string(c.bits);
  constexpr double kFar = 1e9;
  // Directions from the canvas centre; with three far vertices they are drawn until they do not
  // all lie in one half-plane, so the triangle contains the canvas centre and covers the canvas.
  std::array<Vec2, 3> dir;
  for (;;) {
    for (Vec2& d : dir) rng.direction(d.x, d.y);
    if (far_count < 3) break;
    const auto cross = [](Vec2 u, Vec2 v) { return u.x * v.y - u.y * v.x; };
    const double c01 = cross(dir[0], dir[1]), c12 = cross(dir[1], dir[2]),
                 c20 = cross(dir[2], dir[0]);
    if ((c01 > 0 && c12 > 0 && c20 > 0) || (c01 < 0 && c12 < 0 && c20 < 0)) break;
  }
  std::array<Vec2, 3> v;
  for (int i = 0; i < 3; ++i) {
    if (i < far_count) {
      const double r = rng.scale(1e3, kFar);
      v[i] = {std::clamp(256 + r * dir[i].x, -kFar, kFar),
              std::clamp(256 + r * dir[i].y, -kFar, kFar)};
      // Now and then a coordinate exactly at the bound, so the family reaches ±1e9 itself.
      if (rng.chance(1, 6)) v[i].x = v[i].x < 0 ? -kFar : kFar;
      if (rng.chance(1, 6)) v[i].y = v[i].y < 0 ? -kFar : kFar;
    } else {
      v[i] = {rng.uniform(-64, 576), rng.uniform(-64, 576)};
    }
  }
  set_triangle(rng, c, v[0], v[1], v[2]);
}

void generate_subpixel(Rng& rng, StressCase& c) {
  c.bits = rng.coin() ? 8 : 12;
  c.width = c.height = 64;
  const double box = rng.scale(std::ldexp(4.0, -c.bits), 0.98);
  c.kind = "box " + std::to_string(box).substr(0, 6);
  // Near a pixel centre half of the time, so that the box often holds exactly one centre.
  const auto corner = [&] {
    const double centre = static_cast<double>(rng.integer(-1, 64));
    return rng.coin() ? centre - rng.uniform(0, box) : centre + rng.uniform(-0.5, 0.5);
  };
  const double ox = corner(), oy = corner();
  const Vec2 o{ox, oy};
  const auto vertex = [&] { return Vec2{o.x + rng.uniform(0, box), o.y + rng.uniform(0, box)}; };
  const Vec2 a = vertex(), b = vertex(), d = vertex();
  // The box is below one pixel after rounding to the grid too: box + 2^-bits ≤ 0.98 + 1/256 < 1.
  set_triangle(rng, c, a, b, d);
}

void generate_near_horizontal(Rng& rng, StressCase& c) {
  // Slopes this small need the fine grid: on 1/4096 px a rise of k units over dx px has slope
  // k / (4096 dx), so 1e-6 takes dx ≈ 244 k px.
  c.bits = 12;
  const double unit = std::ldexp(1.0, -c.bits);
  const double slope = rng.scale(1e-6, 0.1);
  std::int64_t k = rng.integer(1, 16);
  const double max_run = 2500;
  if (k * unit / slope > max_run)
    k = std::max<std::int64_t>(1, static_cast<std::int64_t>(max_run * slope / unit));
  const double rise = static_cast<double>(k) * unit * (rng.coin() ? 1 : -1);
  const double run = std::abs(rise) / slope * (rng.coin() ? 1 : -1);
  // The edge starts on, or a few grid units off, a row of pixel centres: where a drifting or
  // rounded x decides the fate of whole runs of pixels.
  double offset = 0;
  switch (rng.integer(0, 2)) {
    case 0:
      offset = 0;
      break;
    case 1:
      offset = static_cast<double>(rng.integer(-8, 8)) * unit;
      break;
    default:
      offset = rng.uniform(-0.5, 0.5);
  }
  const Vec2 a{rng.uniform(-200, 400) - std::min(run, 0.0) * 0.5,
               static_cast<double>(rng.integer(0, 511)) + offset};
  const Vec2 a_grid = on_grid(a, c.bits);
  const Vec2 b{a_grid.x + run, a_grid.y + rise};  // b.y stays on the grid: rise is k units
  const double t = rng.unit();
  const double across = rng.scale(0.5, 300) * (rng.coin() ? 1 : -1);
  const Vec2 d{a_grid.x + t * run + rng.uniform(-50, 50), a_grid.y + t * rise + across};
  c.kind = "slope " + std::to_string(slope).substr(0, 8);
  set_triangle(rng, c, a_grid, b, d);
}

void generate_near_vertical(Rng& rng, StressCase& c) {
  generate_near_horizontal(rng, c);
  transpose(c);
}

void generate_on_lattice(Rng& rng, StressCase& c, double offset) {
  // Integers are on every grid, k + 0.5 on every grid but the whole-pixel one.
  c.bits = offset == 0 ? (rng.coin() ? 0 : 8) : (rng.coin() ? 1 : 8);
  c.kind = "bits " + std::to_string(c.bits);
  const std::int64_t size = static_cast<std::int64_t>(rng.scale(1, 600));
  const std::int64_t ax = rng.integer(-16, 528), ay = rng.integer(-16, 528);
  const auto vertex = [&](std::int64_t x, std::int64_t y) {
    return Vec2{static_cast<double>(x) + offset, static_cast<double>(y) + offset};
  };
  const Vec2 a = vertex(ax, ay);
  const Vec2 b = vertex(ax + rng.integer(-size, size), ay + rng.integer(-size, size));
  const Vec2 d = vertex(ax + rng.integer(-size, size), ay + rng.integer(-size, size));
  set_triangle(rng, c, a, b, d);
}

void generate_long_span(Rng& rng, StressCase& c) {
  c.bits = 8;
  c.width = 16384;
  c.height = static_cast<int>(rng.integer(4, 24));
  const double h = c.height;
  // One vertex beyond each end of the canvas, so that the spans run the whole 16,384 pixels, and
  // the third either on the canvas rows or far above or below (taller, steeper edges).
  const Vec2 a{rng.uniform(-64, -0.5), rng.uniform(-6, h + 6)};
  const Vec2 b{rng.uniform(16384, 16448), rng.uniform(-6, h + 6)};
  Vec2 d{rng.uniform(-64, 16448), rng.uniform(-6, h + 6)};
  c.kind = "flat";
  if (rng.coin()) {
    c.kind = "tall";
    d.y = rng.coin() ? -rng.uniform(50, 5000) : h + rng.uniform(50, 5000);
  }
  set_triangle(rng, c, a, b, d);
}

}  // namespace scantrace::stress::detail
