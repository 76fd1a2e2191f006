// The mesh family: triangles that tile a rectangle exactly, so that under the top-left rule every
// pixel the rectangle owns must be written once and no other pixel at all. Built in integer grid
// units, where "tiles exactly" can be checked exactly: shared vertices are bit-identical and every
// triangle has the orientation of the rectangle.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "stress/generators.hpp"
#include "stress/grid.hpp"

namespace scantrace::stress::detail {
namespace {

using i64 = std::int64_t;

struct GridPoint {
  i64 x = 0, y = 0;
};

// Twice the signed area of (a, b, d) in grid units² (|coordinates| < 2^20 here: exact in i64).
i64 cross(GridPoint a, GridPoint b, GridPoint d) {
  return (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
}

struct Mesh {
  std::vector<GridPoint> points;
  std::vector<Color> colors;  // one per point: neighbouring triangles share vertex colours
  std::vector<std::array<int, 3>> faces;

  int add(Rng& rng, GridPoint p) {
    points.push_back(p);
    colors.push_back(random_color(rng));
    return static_cast<int>(points.size()) - 1;
  }
};

struct Rect {
  i64 x0, y0, x1, y1;  // grid units
};

// The rim of a fan: the four corners and distinct random points on the sides, in order around
// the rectangle, so that consecutive rim points always lie on one side.
std::vector<GridPoint> fan_rim(Rng& rng, const Rect& r, int count) {
  const i64 w = r.x1 - r.x0, h = r.y1 - r.y0, perimeter = 2 * (w + h);
  std::vector<i64> at{0, w, w + h, 2 * w + h};
  while (static_cast<int>(at.size()) < count) {
    at.push_back(rng.integer(0, perimeter - 1));
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
  }
  std::vector<GridPoint> rim;
  for (i64 u : at) {
    if (u < w)
      rim.push_back({r.x0 + u, r.y0});  // top
    else if (u < w + h)
      rim.push_back({r.x1, r.y0 + (u - w)});  // right
    else if (u < 2 * w + h)
      rim.push_back({r.x1 - (u - w - h), r.y1});  // bottom
    else
      rim.push_back({r.x0, r.y1 - (u - 2 * w - h)});  // left
  }
  return rim;
}

void fan(Rng& rng, const Rect& r, Mesh& m, i64 unit) {
  const GridPoint centre{rng.integer(r.x0 + unit, r.x1 - unit),
                         rng.integer(r.y0 + unit, r.y1 - unit)};
  const int c = m.add(rng, centre);
  const std::vector<GridPoint> rim = fan_rim(rng, r, 1000);
  const int first = static_cast<int>(m.points.size());
  for (const GridPoint& p : rim) m.add(rng, p);
  const int n = static_cast<int>(rim.size());
  for (int k = 0; k < n; ++k) m.faces.push_back({c, first + k, first + (k + 1) % n});
}

// A jittered nx × ny grid, each cell split along a random diagonal. Side vertices slide only along
// their side, corners stay; a jitter of at most a fifth of a cell keeps every cell convex, and the
// diagonal is switched in the (never expected) case that a triangle would come out inverted.
// Without jitter on a rectangle with integer corners the vertices are whole pixels: every shared
// edge then runs through pixel centres, the hardest case for the tie rule.
void grid(Rng& rng, const Rect& r, Mesh& m, bool jitter, i64 unit) {
  const int nx = static_cast<int>(rng.integer(2, 20)), ny = static_cast<int>(rng.integer(2, 20));
  const i64 w = r.x1 - r.x0, h = r.y1 - r.y0;
  std::vector<int> id((nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      GridPoint p{r.x0 + w * i / nx, r.y0 + h * j / ny};
      if (!jitter) {
        p.x = r.x0 + (p.x - r.x0) / unit * unit;
        p.y = r.y0 + (p.y - r.y0) / unit * unit;
      } else {
        const i64 jx = w / nx / 5, jy = h / ny / 5;
        if (i > 0 && i < nx) p.x += rng.integer(-jx, jx);
        if (j > 0 && j < ny) p.y += rng.integer(-jy, jy);
      }
      id[j * (nx + 1) + i] = m.add(rng, p);
    }
  const i64 sign = cross({r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}) > 0 ? 1 : -1;
  const auto ok = [&](int a, int b, int d) {
    return sign * cross(m.points[a], m.points[b], m.points[d]) > 0;
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id[j * (nx + 1) + i], b = id[j * (nx + 1) + i + 1];
      const int d = id[(j + 1) * (nx + 1) + i + 1], e = id[(j + 1) * (nx + 1) + i];
      const bool first = rng.coin();
      if ((first && ok(a, b, d) && ok(a, d, e)) || !(ok(a, b, e) && ok(b, d, e))) {
        m.faces.push_back({a, b, d});
        m.faces.push_back({a, d, e});
      } else {
        m.faces.push_back({a, b, e});
        m.faces.push_back({b, d, e});
      }
    }
}

// Repeated 1-to-3 splits at random interior points: a valid triangulation at every step, and one
// that grows ever thinner triangles (points near an edge are favoured now and then), all sharing
// edges with their neighbours.
void split(Rng& rng, const Rect& r, Mesh& m) {
  const int a = m.add(rng, {r.x0, r.y0}), b = m.add(rng, {r.x1, r.y0});
  const int d = m.add(rng, {r.x1, r.y1}), e = m.add(rng, {r.x0, r.y1});
  if (rng.coin()) {
    m.faces = {{a, b, d}, {a, d, e}};
  } else {
    m.faces = {{a, b, e}, {b, d, e}};
  }
  const int insertions = static_cast<int>(rng.integer(150, 450));
  for (int k = 0; k < insertions; ++k) {
    const std::size_t f =
        static_cast<std::size_t>(rng.integer(0, static_cast<i64>(m.faces.size()) - 1));
    const auto [i0, i1, i2] = m.faces[f];
    const GridPoint p0 = m.points[i0], p1 = m.points[i1], p2 = m.points[i2];
    double w0 = rng.unit(), w1 = rng.unit(), w2 = rng.unit();
    if (rng.chance(1, 3)) w2 *= 1e-3;  // near the edge p0–p1
    const double sum = w0 + w1 + w2;
    if (!(sum > 0)) continue;
    const auto mix = [&](i64 u0, i64 u1, i64 u2) {
      return std::llround((w0 * static_cast<double>(u0) + w1 * static_cast<double>(u1) +
                           w2 * static_cast<double>(u2)) /
                          sum);
    };
    const GridPoint p{mix(p0.x, p1.x, p2.x), mix(p0.y, p1.y, p2.y)};
    // Strictly inside after rounding to the grid, or the split would make a degenerate or
    // inverted triangle: then this attempt is simply skipped.
    const i64 whole = cross(p0, p1, p2);
    const auto same_side = [&](i64 v) { return whole > 0 ? v > 0 : v < 0; };
    if (!same_side(cross(p0, p1, p)) || !same_side(cross(p1, p2, p)) ||
        !same_side(cross(p2, p0, p)))
      continue;
    const int n = m.add(rng, p);
    m.faces[f] = {i0, i1, n};
    m.faces.push_back({i1, i2, n});
    m.faces.push_back({i2, i0, n});
  }
}

}  // namespace

void generate_mesh(Rng& rng, StressCase& c) {
  // The default grid mostly, now and then a coarse or the finest one: the thinnest triangles
  // (and the most centres exactly on shared edges) come with the finest.
  static constexpr int kBits[] = {4, 8, 8, 12};
  c.bits = kBits[rng.integer(0, 3)];
  const i64 unit = i64{1} << c.bits;
  // Integer corners a third of the time: every side then runs through pixel centres.
  const bool integer = rng.chance(1, 3);
  const auto coordinate = [&](double lo, double hi) {
    const i64 v = rng.integer(static_cast<i64>(lo * unit), static_cast<i64>(hi * unit));
    return integer ? v / unit * unit : v;
  };
  Rect r;
  r.x0 = coordinate(-24, 200);
  r.y0 = coordinate(-24, 200);
  r.x1 = r.x0 + coordinate(96, 330);
  r.y1 = r.y0 + coordinate(96, 330);
  Mesh m;
  switch (c.index % 3) {
    case 0:
      c.kind = "fan";
      fan(rng, r, m, unit);
      break;
    case 1: {
      const bool jitter = !integer || rng.coin();
      c.kind = jitter ? "grid" : "integer grid";
      grid(rng, r, m, jitter, integer ? unit : 1);
      break;
    }
    default:
      c.kind = "split";
      split(rng, r, m);
  }
  if (integer) c.kind += ", integer corners";
  c.kind += ", bits " + std::to_string(c.bits);
  const auto pixel = [&](GridPoint p) {
    return Vec2{from_units(p.x, c.bits), from_units(p.y, c.bits)};
  };
  c.region = {pixel({r.x0, r.y0}), pixel({r.x1, r.y0}), pixel({r.x1, r.y1}), pixel({r.x0, r.y1})};
  c.triangles.reserve(m.faces.size());
  for (const auto& f : m.faces) {
    Triangle t;
    for (int k = 0; k < 3; ++k) {
      t.v[k] = pixel(m.points[f[k]]);
      t.c[k] = m.colors[f[k]];
    }
    c.triangles.push_back(t);
  }
}

}  // namespace scantrace::stress::detail
