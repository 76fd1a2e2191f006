#pragma once
// The other classic family, for comparison with the edge table: visit every pixel of the
// bounding box (clipped to the canvas) and test its centre against the three edge functions, as
// tinyrenderer does with barycentric coordinates. The edge functions are exact integers on the
// snapped vertices, stepped by one constant per pixel, and ties follow the same top-left (or
// closed) rule, so coverage equals the exact edge-table fill's; the cost is the whole bounding box
// rather than the triangle. Gouraud colours are the barycentric weights at the pixel centre.
#include <algorithm>
#include <array>
#include <span>

#include "canvas.hpp"
#include "fill_options.hpp"
#include "fill_result.hpp"

namespace scantrace {

namespace detail {

// The triangle's vertices in a canonical order, by (y, x) on the grid, with the outline flag of
// each of its edges carried along. The edge functions are exact whatever the order, but a Gouraud
// colour w0·c0 + w1·c1 + w2·c2 is summed in double in vertex order: two listings of one triangle
// could differ in the last bit, and stored as float32 that bit showed in a stress run (random
// family, seed 20261123, case 2698). Summing in this order makes the colour a function of the
// triangle, as flat_color makes the flat one.
struct CanonicalTriangle {
  std::array<FixedPoint, 3> v;
  std::array<Color, 3> colors;
  std::array<bool, 3> outline;  // edge i runs from v[i] to v[i + 1]
};

inline CanonicalTriangle canonical_triangle(const std::array<FixedPoint, 3>& v,
                                            const std::array<Color, 3>& colors,
                                            std::array<bool, 3> outline) {
  std::array<int, 3> k{0, 1, 2};
  const auto before = [&](int a, int b) {
    return v[a].y != v[b].y ? v[a].y < v[b].y : v[a].x < v[b].x;
  };
  if (before(k[1], k[0])) std::swap(k[0], k[1]);
  if (before(k[2], k[1])) std::swap(k[1], k[2]);
  if (before(k[1], k[0])) std::swap(k[0], k[1]);
  CanonicalTriangle t;
  for (int i = 0; i < 3; ++i) {
    t.v[i] = v[k[i]];
    t.colors[i] = colors[k[i]];
    // The given edge joining vertices a and b is the one that starts at whichever of them the
    // other follows.
    const int a = k[i], b = k[(i + 1) % 3];
    t.outline[i] = outline[b == (a + 1) % 3 ? a : b];
  }
  return t;
}

template <Canvas C>
FillResult fill_halfspace_triangle(C& canvas, const std::array<FixedPoint, 3>& given,
                                   const std::array<Color, 3>& given_colors, const FillOptions& opt,
                                   Color flat,
                                   std::array<bool, 3> given_outline = {true, true, true}) {
  const auto [v, colors, outline] = canonical_triangle(given, given_colors, given_outline);
  const SubpixelGrid grid(opt.subpixel_bits);
  const i64 s = grid.scale();
  const i128 area2 = static_cast<i128>(v[1].x - v[0].x) * (v[2].y - v[0].y) -
                     static_cast<i128>(v[1].y - v[0].y) * (v[2].x - v[0].x);
  FillResult result;
  if (area2 == 0) return result;
  const int sign = area2 > 0 ? 1 : -1;
  const bool closed = opt.fill_rule == FillRule::closed;

  // Edge i runs from v[i] to v[i+1]; E_i(p) = sign·((b−a) × (p−a)) is positive inside. A centre
  // on the edge (E_i = 0) belongs to the triangle under the top-left rule when the edge is a left
  // edge (the interior lies to its right, ∂E/∂x > 0) or a top edge (horizontal, interior below).
  std::array<i64, 3> ex{}, ey{};  // ∂E_i/∂x and ∂E_i/∂y per grid unit
  std::array<bool, 3> owns_ties{};
  for (int i = 0; i < 3; ++i) {
    const FixedPoint a = v[i], b = v[(i + 1) % 3];
    ex[i] = -sign * (b.y - a.y);
    ey[i] = sign * (b.x - a.x);
    // The closed rule takes the centres on the polygon's outline; a diagonal inside a fan
    // (outline[i] false) keeps the top-left rule, so that its centres go to one side only.
    owns_ties[i] = (closed && outline[i]) || ex[i] > 0 || (ex[i] == 0 && ey[i] > 0);
  }
  const i64 x_min = std::min({v[0].x, v[1].x, v[2].x}), x_max = std::max({v[0].x, v[1].x, v[2].x});
  const i64 y_min = std::min({v[0].y, v[1].y, v[2].y}), y_max = std::max({v[0].y, v[1].y, v[2].y});
  const i64 col0 = std::max<i64>(grid.ceil_to_pixel(x_min), 0);
  const i64 col1 = std::min<i64>(grid.floor_to_pixel(x_max), canvas.width() - 1);
  const RowBand band = canvas_rows(canvas);
  const i64 row0 = std::max<i64>(grid.ceil_to_pixel(y_min), band.begin);
  const i64 row1 = std::min<i64>(grid.floor_to_pixel(y_max), band.end - 1);
  const bool gouraud = opt.shading == Shading::gouraud;
  const double inv_area = 1.0 / static_cast<double>(area2 * sign);

  for (i64 y = row0; y <= row1; ++y) {
    ++result.rows;
    std::array<i128, 3> e;  // at the centre of pixel (col0, y)
    for (int i = 0; i < 3; ++i)
      e[i] = static_cast<i128>(ex[i]) * (col0 * s - v[i].x) +
             static_cast<i128>(ey[i]) * (y * s - v[i].y);
    i64 run_begin = -1, run_end = -1;  // a convex shape meets a row in one run
    for (i64 x = col0; x <= col1; ++x) {
      bool inside = true;
      for (int i = 0; i < 3; ++i) inside &= e[i] > 0 || (e[i] == 0 && owns_ties[i]);
      if (inside) {
        if (run_begin < 0) run_begin = x;
        run_end = x + 1;
        if (gouraud) {
          // The weight of vertex k is the edge function of the edge opposite it.
          const double w0 = static_cast<double>(e[1]) * inv_area;
          const double w1 = static_cast<double>(e[2]) * inv_area;
          const double w2 = static_cast<double>(e[0]) * inv_area;
          canvas.set(static_cast<int>(x), static_cast<int>(y),
                     colors[0] * w0 + colors[1] * w1 + colors[2] * w2);
        }
      } else if (run_begin >= 0) {
        break;
      }
      for (int i = 0; i < 3; ++i) e[i] += static_cast<i128>(ex[i]) * s;
    }
    if (run_begin >= 0) {
      if (!gouraud)
        canvas.fill_span(static_cast<int>(y), static_cast<int>(run_begin),
                         static_cast<int>(run_end), flat);
      result.pixels += run_end - run_begin;
    }
  }
  return result;
}

}  // namespace detail

// A convex polygon by half-space tests: a triangle directly, a larger polygon as the fan of
// triangles (v0, vi, vi+1), which the tie rule makes tile the polygon exactly — each pixel once.
// Under the closed rule only the outline's edges take their ties: were the diagonals closed too,
// the centres on them would be filled (and counted) by both of their triangles.
template <Canvas C>
FillResult fill_halfspace(C& canvas, std::span<const FixedPoint> pts, std::span<const Color> colors,
                          const FillOptions& opt, Color flat) {
  FillResult total;
  for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
    const FillResult r = detail::fill_halfspace_triangle(canvas, {pts[0], pts[i], pts[i + 1]},
                                                         {colors[0], colors[i], colors[i + 1]}, opt,
                                                         flat, {i == 1, true, i + 2 == pts.size()});
    total.rows += r.rows;
    total.pixels += r.pixels;
  }
  return total;
}

}  // namespace scantrace
