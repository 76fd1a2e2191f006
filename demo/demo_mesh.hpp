#pragma once
// A mesh the project generates itself, so that `scantrace demo` needs no file: a torus.
#include "src/mesh.hpp"

namespace scantrace {

// A torus around the y axis (ring radius R, tube radius r), `rings` × `sides` quads split into
// triangles, counter-clockwise from outside, tilted by `tilt_degrees` about the x axis so that
// the hole and both sides show. Vertex colours run round the ring (a hue sweep), so the demo
// shows file-style vertex colours, lighting and Gouraud interpolation at once.
Mesh demo_torus(double R = 1.0, double r = 0.4, int rings = 48, int sides = 24,
                double tilt_degrees = 55);

}  // namespace scantrace
