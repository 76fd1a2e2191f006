#include "reference/exact_reference.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace scantrace::reference {

i64 snap(double v, int bits) {
  const double scaled = std::ldexp(v, bits);  // exact: a power-of-two scaling
  const double f = std::floor(scaled);
  // scaled − f is exact (f is scaled with its fractional bits cleared) and 0 for |scaled| ≥ 2^52,
  // where every double is an integer. f + 0.5 is NOT exact there: at 2^52 and above it rounds
  // (ties to even) to f or f + 1, which moved such points one grid unit.
  return static_cast<i64>(f) + (scaled - f >= 0.5 ? 1 : 0);
}

GridPt snap(scantrace::Vec2 p, int bits) {
  return {snap(p.x, bits), snap(p.y, bits)};
}

i64 floor_div(i64 a, i64 b) {
  const i64 q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

i64 ceil_div(i64 a, i64 b) {
  return -floor_div(-a, b);
}

Polygon::Polygon(std::span<const scantrace::Vec2> points, int bits) : scale_(i64{1} << bits) {
  for (const scantrace::Vec2& p : points) v_.push_back(snap(p, bits));
  const std::size_t n = v_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const GridPt a = v_[i], b = v_[(i + 1) % n];
    twice_area_ += static_cast<i128>(a.x) * b.y - static_cast<i128>(b.x) * a.y;
  }
  orientation_ = twice_area_ > 0 ? 1 : twice_area_ < 0 ? -1 : 0;
  // With y pointing down, the gradient of the (oriented) edge function is the inward normal
  // orientation · (-dy, dx). Left edge: the normal points right. Top edge: horizontal with the
  // normal pointing down (interior at larger y).
  for (std::size_t i = 0; i < n; ++i) {
    const GridPt a = v_[i], b = v_[(i + 1) % n];
    const i64 dx = b.x - a.x, dy = b.y - a.y;
    const bool left = orientation_ * -dy > 0;
    const bool top = dy == 0 && orientation_ * dx > 0;
    owns_ties_.push_back(left || top);
  }
  min_ = max_ = v_.empty() ? GridPt{} : v_[0];
  for (const GridPt& p : v_) {
    min_.x = std::min(min_.x, p.x), min_.y = std::min(min_.y, p.y);
    max_.x = std::max(max_.x, p.x), max_.y = std::max(max_.y, p.y);
  }
}

i128 Polygon::raw_edge(std::size_t i, i64 gx, i64 gy) const {
  const GridPt a = v_[i], b = v_[(i + 1) % v_.size()];
  return static_cast<i128>(b.x - a.x) * (gy - a.y) - static_cast<i128>(b.y - a.y) * (gx - a.x);
}

i128 Polygon::inside(std::size_t i, i64 gx, i64 gy) const {
  return orientation_ * raw_edge(i, gx, gy);
}

bool Polygon::covers(i64 px, i64 py, FillRule rule) const {
  if (degenerate()) return false;
  const i64 gx = px * scale_, gy = py * scale_;
  for (std::size_t i = 0; i < v_.size(); ++i) {
    const i128 e = inside(i, gx, gy);
    if (e < 0) return false;
    if (e == 0 && rule == FillRule::top_left && !owns_ties_[i]) return false;
  }
  return true;
}

std::array<double, 3> Polygon::barycentric(i64 px, i64 py) const {
  if (v_.size() != 3) throw std::logic_error("barycentric weights are defined for triangles");
  const i64 gx = px * scale_, gy = py * scale_;
  // The weight of vertex k is the sub-area opposite to it over the whole area; all exact until
  // the final division.
  const double area = static_cast<double>(twice_area_);
  return {static_cast<double>(raw_edge(1, gx, gy)) / area,
          static_cast<double>(raw_edge(2, gx, gy)) / area,
          static_cast<double>(raw_edge(0, gx, gy)) / area};
}

Raster rasterize(int width, int height, std::span<const scantrace::Vec2> points,
                 std::span<const scantrace::Color> colors, FillRule rule, int bits) {
  Raster out;
  out.width = width;
  out.height = height;
  out.covered.assign(static_cast<std::size_t>(width) * height, 0);
  out.color.assign(out.covered.size(), scantrace::Color{});
  const Polygon poly(points, bits);
  const bool interpolate = points.size() == 3 && colors.size() == 3;
  // The bounding box only saves time: every centre outside it fails some half-plane test anyway.
  const i64 x0 = std::max<i64>(poly.min_px(), 0), x1 = std::min<i64>(poly.max_px(), width - 1);
  const i64 y0 = std::max<i64>(poly.min_py(), 0), y1 = std::min<i64>(poly.max_py(), height - 1);
  for (i64 y = y0; y <= y1; ++y) {
    for (i64 x = x0; x <= x1; ++x) {
      if (!poly.covers(x, y, rule)) continue;
      const std::size_t k = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
      out.covered[k] = 1;
      ++out.count;
      if (interpolate) {
        const std::array<double, 3> w = poly.barycentric(x, y);
        out.color[k] = colors[0] * w[0] + colors[1] * w[1] + colors[2] * w[2];
      }
    }
  }
  return out;
}

namespace {

// One edge of a general polygon, oriented top to bottom, with its winding and vertex colours.
struct RefEdge {
  GridPt top, bottom;
  int winding = 0;
  int id = 0;
  scantrace::Color c_top, c_bottom;
};

// Where an edge crosses row gy (grid units): x = q + r / den grid units, 0 <= r < den, exactly.
// The numerator needs up to 2^123, so crossings are compared as (q, r / den), never
// cross-multiplied whole.
struct Crossing {
  i128 q = 0;
  i64 r = 0, den = 1;
  const RefEdge* edge = nullptr;
};

Crossing cross(const RefEdge& e, i64 gy) {
  const i64 dy = e.bottom.y - e.top.y;
  const i128 num =
      static_cast<i128>(e.top.x) * dy + static_cast<i128>(e.bottom.x - e.top.x) * (gy - e.top.y);
  i128 q = num / dy;
  if (num % dy < 0) --q;
  return {q, static_cast<i64>(num - q * dy), dy, &e};
}

// The crossing lies at or left of the grid x `gx`.
bool at_or_left(const Crossing& c, i64 gx) {
  return c.q < gx || (c.q == gx && c.r == 0);
}

// The order of two crossings along the row, ties by slope (the order just below the row) and id.
bool before(const Crossing& a, const Crossing& b) {
  if (a.q != b.q) return a.q < b.q;
  const i128 l = static_cast<i128>(a.r) * b.den, r = static_cast<i128>(b.r) * a.den;
  if (l != r) return l < r;
  const RefEdge &ea = *a.edge, &eb = *b.edge;
  const i128 sa = static_cast<i128>(ea.bottom.x - ea.top.x) * (eb.bottom.y - eb.top.y);
  const i128 sb = static_cast<i128>(eb.bottom.x - eb.top.x) * (ea.bottom.y - ea.top.y);
  if (sa != sb) return sa < sb;
  return ea.id < eb.id;
}

bool inside_by(int winding, WindingRule rule) {
  return rule == WindingRule::even_odd ? (winding & 1) != 0 : winding != 0;
}

double to_double(const Crossing& c, i64 scale) {
  return (static_cast<double>(c.q) + static_cast<double>(c.r) / static_cast<double>(c.den)) /
         static_cast<double>(scale);
}

scantrace::Color edge_color(const RefEdge& e, i64 gy) {
  const double t = static_cast<double>(gy - e.top.y) / static_cast<double>(e.bottom.y - e.top.y);
  return e.c_top + (e.c_bottom - e.c_top) * t;
}

}  // namespace

Raster rasterize_contours(int width, int height,
                          std::span<const std::vector<scantrace::Vec2>> contours,
                          std::span<const scantrace::Color> colors, WindingRule rule, int bits) {
  Raster out;
  out.width = width;
  out.height = height;
  out.covered.assign(static_cast<std::size_t>(width) * height, 0);
  out.color.assign(out.covered.size(), scantrace::Color{});
  const i64 scale = i64{1} << bits;
  std::size_t total = 0;
  for (const auto& c : contours) total += c.size();
  const bool shade = colors.size() == total;
  std::vector<RefEdge> edges;
  int base = 0;
  for (const auto& c : contours) {
    const int n = static_cast<int>(c.size());
    for (int k = 0; k < n; ++k) {
      const int i = base + k, j = base + (k + 1) % n;
      const GridPt a = snap(c[k], bits), b = snap(c[(k + 1) % n], bits);
      if (a.y == b.y) continue;  // crosses no row
      RefEdge e;
      e.id = i;
      e.winding = a.y < b.y ? 1 : -1;
      e.top = a.y < b.y ? a : b;
      e.bottom = a.y < b.y ? b : a;
      if (shade) {
        e.c_top = a.y < b.y ? colors[i] : colors[j];
        e.c_bottom = a.y < b.y ? colors[j] : colors[i];
      }
      edges.push_back(e);
    }
    base += n;
  }
  std::vector<Crossing> row;
  for (i64 y = 0; y < height; ++y) {
    const i64 gy = y * scale;
    row.clear();
    for (const RefEdge& e : edges)
      if (e.top.y <= gy && gy < e.bottom.y) row.push_back(cross(e, gy));
    if (row.empty()) continue;
    if (shade) std::sort(row.begin(), row.end(), before);
    for (i64 x = 0; x < width; ++x) {
      const i64 gx = x * scale;
      // The definition, literally: the signed crossings at or left of the centre.
      int winding = 0;
      for (const Crossing& c : row)
        if (at_or_left(c, gx)) winding += c.edge->winding;
      if (!inside_by(winding, rule)) continue;
      const std::size_t k = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
      out.covered[k] = 1;
      ++out.count;
      if (!shade) continue;
      // The inside run holding the pixel: walk the ordered crossings, remembering where the rule
      // last turned inside, until the first crossing right of the centre that turns it outside.
      int w = 0;
      const Crossing* open = nullptr;
      for (const Crossing& c : row) {
        w += c.edge->winding;
        const bool now = inside_by(w, rule);
        if (now && !open) {
          open = &c;
        } else if (!now && open) {
          if (!at_or_left(c, gx)) {
            const double xl = to_double(*open, scale), xr = to_double(c, scale);
            const scantrace::Color cl = edge_color(*open->edge, gy), cr = edge_color(*c.edge, gy);
            const double t = xr > xl ? (static_cast<double>(x) - xl) / (xr - xl) : 0.0;
            out.color[k] = cl + (cr - cl) * t;
            break;
          }
          open = nullptr;
        }
      }
    }
  }
  return out;
}

scantrace::Color mean_color(std::span<const scantrace::Color> colors) {
  scantrace::Color sum;
  for (const scantrace::Color& c : colors) sum += c;
  return sum * (1.0 / static_cast<double>(colors.size()));
}

}  // namespace scantrace::reference
