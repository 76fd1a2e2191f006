#pragma once
// The depth of a triangle at a pixel centre: the plane through its three (x, y, depth) points,
// the vertices taken as snapped (in pixels). One definition, used by the z-buffer render
// (zbuffer_canvas.hpp) and by anything that must reproduce its decisions bit for bit (the replay
// of a z-buffered trace recomputes every pixel's depth test from the trace with it).
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
};

}  // namespace scantrace
