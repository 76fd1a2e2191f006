#include "grade/face_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace scantrace::grade {
namespace {

using reference::i128;
using reference::i64;

std::array<Vec2, 3> face_points(const Scene& scene, int f) {
  const auto& v = scene.faces[f];
  return {scene.vertices[v[0]], scene.vertices[v[1]], scene.vertices[v[2]]};
}

double segment_distance(Vec2 a, Vec2 b, double x, double y) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((x - a.x) * dx + (y - a.y) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(a.x + t * dx - x, a.y + t * dy - y);
}

}  // namespace

FaceGeometry::FaceGeometry(const Scene& scene, int face, int bits)
    : face_(face), polygon_(face_points(scene, face), bits) {
  const auto pts = face_points(scene, face);
  const double scale = std::ldexp(1.0, bits);
  for (int i = 0; i < 3; ++i) {
    g_[i] = reference::snap(pts[i], bits);
    p_[i] = {static_cast<double>(g_[i].x) / scale, static_cast<double>(g_[i].y) / scale};
    colors_[i] = scene.vcolors[scene.faces[face][i]];
  }
  twice_area_ =
      (p_[1].x - p_[0].x) * (p_[2].y - p_[0].y) - (p_[2].x - p_[0].x) * (p_[1].y - p_[0].y);
  scale_ = static_cast<i64>(scale);
}

OnOutline FaceGeometry::on_outline(int x, int y, int* edge) const {
  const i64 px = static_cast<i64>(x) * scale_, py = static_cast<i64>(y) * scale_;
  for (int i = 0; i < 3; ++i)
    if (g_[i].x == px && g_[i].y == py) {
      if (edge) *edge = i;
      return OnOutline::vertex;
    }
  for (int i = 0; i < 3; ++i) {
    const auto a = g_[i], b = g_[(i + 1) % 3];
    const i128 cross =
        static_cast<i128>(b.x - a.x) * (py - a.y) - static_cast<i128>(b.y - a.y) * (px - a.x);
    if (cross != 0) continue;
    if (px < std::min(a.x, b.x) || px > std::max(a.x, b.x) || py < std::min(a.y, b.y) ||
        py > std::max(a.y, b.y))
      continue;
    if (edge) *edge = i;
    return OnOutline::edge;
  }
  return OnOutline::no;
}

double FaceGeometry::distance_to_outline(double x, double y) const {
  double d = segment_distance(p_[0], p_[1], x, y);
  d = std::min(d, segment_distance(p_[1], p_[2], x, y));
  return std::min(d, segment_distance(p_[2], p_[0], x, y));
}

bool FaceGeometry::within(double x, double y, double d) const {
  if (distance_to_outline(x, y) <= d) return true;
  if (twice_area_ == 0) return false;
  const auto w = weights(x, y);
  return w[0] >= 0 && w[1] >= 0 && w[2] >= 0;
}

std::array<double, 3> FaceGeometry::weights(double x, double y) const {
  const auto& p = p_;
  const double w0 = ((p[1].x - x) * (p[2].y - y) - (p[2].x - x) * (p[1].y - y)) / twice_area_;
  const double w1 = ((p[2].x - x) * (p[0].y - y) - (p[0].x - x) * (p[2].y - y)) / twice_area_;
  return {w0, w1, 1 - w0 - w1};
}

Color FaceGeometry::color_at(double x, double y, Shading shading) const {
  return color_at(x, y, shading, colors_);
}

Color FaceGeometry::color_at(double x, double y, Shading shading,
                             const std::array<Color, 3>& c) const {
  if (shading == Shading::flat || twice_area_ == 0) return reference::mean_color(c);
  const auto w = weights(x, y);
  return c[0] * w[0] + c[1] * w[1] + c[2] * w[2];
}

std::string FaceGeometry::shape(int pixels) const {
  std::string words;
  const auto add = [&](const char* w) { words += (words.empty() ? "" : ", ") + std::string(w); };
  for (int i = 0; i < 3; ++i)
    if (g_[i].y == g_[(i + 1) % 3].y) {
      add("horizontal edge");
      break;
    }
  for (int i = 0; i < 3; ++i)
    if (g_[i].x == g_[(i + 1) % 3].x) {
      add("vertical edge");
      break;
    }
  double longest = 0;
  for (int i = 0; i < 3; ++i)
    longest =
        std::max(longest, std::hypot(p_[(i + 1) % 3].x - p_[i].x, p_[(i + 1) % 3].y - p_[i].y));
  // Height over the longest edge below one pixel: a sliver no wider than a pixel anywhere.
  if (longest > 0 && std::fabs(twice_area_) / longest < 1.0) add("sliver");
  if (pixels <= 3) add("a few pixels only");
  return words.empty() ? "ordinary" : words;
}

}  // namespace scantrace::grade
