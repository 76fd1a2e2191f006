#pragma once
// From model space to the canvas: pixel positions (x right, y down) and a depth per vertex
// (larger = farther, the scene's convention).
//
// orthographic (the default): the camera looks down −z; the model's x/y bounding box is fitted
// to the canvas with a margin, keeping the aspect ratio, y flipped so that up stays up. depth = −z.
// perspective: a pinhole camera at `eye` looking at `target` with a vertical field of view `fov`
// (degrees), world y as "up". depth = −1/z_view: a monotone function of the distance along the
// view axis that is also *linear in screen space* (z_view itself is not), so that interpolating
// it over a triangle like a colour gives the exact per-pixel depth order.
#include <optional>
#include <vector>

#include "mesh.hpp"
#include "vec2.hpp"

namespace scantrace {

struct Camera {
  int width = 512, height = 512;
  double margin = 0.05;  // orthographic fit: fraction of the canvas left free on each side
  bool perspective = false;
  Vec3 eye{0, 0, 3};
  std::optional<Vec3> target;  // none: the centre of the model's bounding box
  double fov_degrees = 45;
};

struct Projection {
  std::vector<Vec2> points;    // pixels
  std::vector<double> depth;   // larger = farther
  std::vector<bool> in_front;  // perspective: the vertex is in front of the eye (ortho: all)
};

// Throws std::invalid_argument for a camera that cannot see (eye at the target, fov outside
// (0, 180), canvas without pixels).
Projection project(const Mesh& mesh, const Camera& camera);

}  // namespace scantrace
