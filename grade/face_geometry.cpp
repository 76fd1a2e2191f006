#include "grade/face_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace scantrace::grade {
namespace {

using reference::i128;
using reference::i64;

std::array<Vec2, 3> face_points(const Scene& scene, int f) {
  const auto& v = scene.faces[f];
  return {scene.vertices[v[0]], scene.vertices[v[1]], scene.vertices[v[2]]};
}

// From the centre (x, y) to the nearest point of segment ab, as a vector: its length is the
// distance.
Vec2 segment_offset(Vec2 a, Vec2 b, double x, double y) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((x - a.x) * dx + (y - a.y) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return {a.x + t * dx - x, a.y + t * dy - y};
}

// The squared lengths of the three offsets need no std::hypot (a libm call of ~20 ns: 35% of a
// Gouraud diff of the course scene went to it, from within() over every face near every differing
// pixel). A squared length is within a relative 4·2^-53 of the true square, hypot within an ulp of
// the true length, so lengths whose squares are farther apart than kSquareMargin are ordered alike
// by both, and a square farther than that from d² decides `hypot <= d` alike: hypot is called
// only where the squares cannot tell, and every result is the one hypot alone gives.
constexpr double kSquareMargin = 1e-9;

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
  const auto [x0, x1] = std::minmax({p_[0].x, p_[1].x, p_[2].x});
  const auto [y0, y1] = std::minmax({p_[0].y, p_[1].y, p_[2].y});
  box_ = {x0, x1, y0, y1};
  box_abs_ = std::fabs(x0) + std::fabs(x1) + std::fabs(y0) + std::fabs(y1);
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
  std::array<Vec2, 3> e;
  std::array<double, 3> sq;
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    e[i] = segment_offset(p_[i], p_[(i + 1) % 3], x, y);
    sq[i] = e[i].x * e[i].x + e[i].y * e[i].y;
    nearest = std::min(nearest, sq[i]);
  }
  // The minimum of hypot over the segments whose squares tie with the least (NaN included).
  double d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    if (!(sq[i] > nearest * (1 + kSquareMargin))) d = std::min(d, std::hypot(e[i].x, e[i].y));
  return d;
}

bool FaceGeometry::outline_within(double x, double y, double d) const {
  if (beyond_box(x, y, d)) return false;
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const Vec2 e = segment_offset(p_[i], p_[(i + 1) % 3], x, y);
    nearest = std::min(nearest, e.x * e.x + e.y * e.y);
  }
  const double d2 = d * d;
  if (d >= 0 && nearest < d2 * (1 - kSquareMargin)) return true;
  if (d >= 0 && nearest > d2 * (1 + kSquareMargin)) return false;
  return distance_to_outline(x, y) <= d;  // the squares cannot tell (or d is negative or NaN)
}

bool FaceGeometry::within(double x, double y, double d) const {
  if (outline_within(x, y, d)) return true;
  if (twice_area_ == 0) return false;
  // weights(x, y) all >= 0, the same expressions, stopping at the first negative one.
  const auto& p = p_;
  const double w0 = ((p[1].x - x) * (p[2].y - y) - (p[2].x - x) * (p[1].y - y)) / twice_area_;
  if (!(w0 >= 0)) return false;
  const double w1 = ((p[2].x - x) * (p[0].y - y) - (p[0].x - x) * (p[2].y - y)) / twice_area_;
  return w1 >= 0 && 1 - w0 - w1 >= 0;
}

// Whether the centre is farther than d from the face's bounding box along x or y, by more than
// any rounding: then it is farther than d from the outline too, and hypot says so. Most faces
// of the grid cell around a pixel are (diff's match_shown_faces asks every one of them).
bool FaceGeometry::beyond_box(double x, double y, double d) const {
  const double gap = std::max({box_[0] - x, x - box_[1], box_[2] - y, y - box_[3]});
  return d >= 0 &&
         gap > d + kSquareMargin * (std::fabs(d) + std::fabs(x) + std::fabs(y) + box_abs_);
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
