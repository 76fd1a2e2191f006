#include "camera.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace scantrace {
namespace {

struct Box {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi = lo * -1.0;
  void add(Vec3 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  Vec3 centre() const { return (lo + hi) * 0.5; }
};

Box bounds(const Mesh& m) {
  Box b;
  // Only the positions faces use: an unused stray vertex must not shrink the model.
  for (const auto& f : m.faces)
    for (int v : f) b.add(m.positions[v]);
  if (m.faces.empty()) b.lo = b.hi = {};
  return b;
}

Projection orthographic(const Mesh& m, const Camera& cam, const Box& box) {
  const double w = cam.width * (1 - 2 * cam.margin), h = cam.height * (1 - 2 * cam.margin);
  const double dx = box.hi.x - box.lo.x, dy = box.hi.y - box.lo.y;
  // One scale for both axes keeps the aspect ratio; a flat (zero-extent) model gets scale 1.
  double s = std::min(dx > 0 ? w / dx : std::numeric_limits<double>::infinity(),
                      dy > 0 ? h / dy : std::numeric_limits<double>::infinity());
  if (!std::isfinite(s)) s = 1;
  const Vec3 c = box.centre();
  // Pixel centres are at integers, so the canvas spans [−0.5, W − 0.5]: its centre is (W−1)/2.
  const double cx = (cam.width - 1) / 2.0, cy = (cam.height - 1) / 2.0;
  Projection p;
  for (const Vec3& v : m.positions) {
    p.points.push_back({cx + s * (v.x - c.x), cy - s * (v.y - c.y)});
    p.depth.push_back(-v.z);
    p.in_front.push_back(true);
  }
  return p;
}

Projection perspective(const Mesh& m, const Camera& cam, const Box& box) {
  if (!(cam.fov_degrees > 0 && cam.fov_degrees < 180))
    throw std::invalid_argument("the field of view must be in (0, 180) degrees");
  const Vec3 target = cam.target.value_or(box.centre());
  const Vec3 f = normalized(target - cam.eye);
  if (length(f) == 0) throw std::invalid_argument("the eye is at the target");
  Vec3 r = normalized(cross(f, Vec3{0, 1, 0}));
  // Looking straight up or down: world y cannot be "up", take z instead.
  if (length(r) == 0) r = normalized(cross(f, Vec3{0, 0, -1}));
  const Vec3 u = cross(r, f);
  const double k = (cam.height / 2.0) / std::tan(cam.fov_degrees * std::numbers::pi / 360);
  const double cx = (cam.width - 1) / 2.0, cy = (cam.height - 1) / 2.0;
  Projection p;
  for (const Vec3& v : m.positions) {
    const Vec3 d = v - cam.eye;
    const double z = dot(d, f);
    const bool front = z > 1e-9;
    const double zz = front ? z : 1e-9;
    p.points.push_back({cx + k * dot(d, r) / zz, cy - k * dot(d, u) / zz});
    p.depth.push_back(-1.0 / zz);
    p.in_front.push_back(front);
  }
  return p;
}

}  // namespace

Projection project(const Mesh& mesh, const Camera& camera) {
  if (camera.width <= 0 || camera.height <= 0)
    throw std::invalid_argument("the canvas must have pixels");
  const Box box = bounds(mesh);
  return camera.perspective ? perspective(mesh, camera, box) : orthographic(mesh, camera, box);
}

}  // namespace scantrace
