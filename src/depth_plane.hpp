#pragma once
// The depth of a triangle at a pixel centre: the plane through its three (x, y, depth) points,
// the vertices taken as snapped (in pixels). One definition, used by the z-buffer render
// (zbuffer_canvas.hpp) and by anything that must reproduce its decisions bit for bit (the replay
// of a z-buffered trace recomputes every pixel's depth test from the trace with it).
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "vec2.hpp"

namespace scantrace {

struct DepthPlane {
  double x0 = 0, y0 = 0, d0 = 0, a = 0, b = 0;

  // `p`: the three snapped vertices in pixels; `d`: their depths. A zero-area triangle (which the
  // fill skips before writing anything) gets the flat plane d[0].
  static DepthPlane through(std::span<const Vec2> p, std::span<const double> d) {
    DepthPlane plane;
    plane.d0 = d[0];
    const double ux = p[1].x - p[0].x, uy = p[1].y - p[0].y, wx = p[2].x - p[0].x,
                 wy = p[2].y - p[0].y;
    const double det = ux * wy - wx * uy;
    plane.x0 = p[0].x, plane.y0 = p[0].y;
    if (det == 0) return plane;
    const double e1 = d[1] - d[0], e2 = d[2] - d[0];
    plane.a = (e1 * wy - e2 * uy) / det;
    plane.b = (ux * e2 - wx * e1) / det;
    return plane;
  }

  double at(int x, int y) const { return d0 + a * (x - x0) + b * (y - y0); }

  // A number at or below at(x, y) for every integer point of [x_lo, x_hi] × [y_lo, y_hi], at()'s
  // rounding included (−infinity when it cannot tell). The plane is affine, so its exact minimum
  // over the box is at a corner; at() rounds two products and two sums, so it may come out below
  // the exact value by at most γ₃·S with S = |d0| + max|a·(x − x0)| + max|b·(y − y0)| over the
  // box (x − x0 is exact: x0 is on the subpixel grid), and the corner evaluated here may come out
  // above its exact value by as much. 16u·S (u = 2⁻⁵³) covers both and the final subtraction.
  double lower_bound(int x_lo, int y_lo, int x_hi, int y_hi) const {
    const double ax0 = a * (x_lo - x0), ax1 = a * (x_hi - x0), by0 = b * (y_lo - y0),
                 by1 = b * (y_hi - y0);
    const double low = d0 + std::min(ax0, ax1) + std::min(by0, by1);
    const double size = std::fabs(d0) + std::max(std::fabs(ax0), std::fabs(ax1)) +
                        std::max(std::fabs(by0), std::fabs(by1));
    const double bound = low - 0x1p-49 * size;
    return std::isfinite(bound) ? bound : -std::numeric_limits<double>::infinity();
  }
};

}  // namespace scantrace
