#include "grade/scene_around.hpp"

#include "grade/pixel_story.hpp"

#include <algorithm>
#include <cmath>

#include "trace/record.hpp"

namespace scantrace::grade {

Scene scene_around(const Scene& scene, int x, int y, double margin, std::vector<int>* faces) {
  Scene out;
  out.width = scene.width, out.height = scene.height, out.background = scene.background;
  std::vector<int> picked = faces_around(scene, x, y, margin);
  for (int f : picked) {
    std::array<int, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const int v = scene.faces[f][k];
      tri[k] = static_cast<int>(out.vertices.size());
      out.vertices.push_back(scene.vertices[v]);
      out.vcolors.push_back(scene.vcolors[v]);
      out.depth.push_back(scene.depth[v]);
    }
    out.faces.push_back(tri);
  }
  if (faces) *faces = std::move(picked);
  return out;
}

double snap_margin(const FillOptions& options) {
  return std::ldexp(0.5, -std::clamp(options.subpixel_bits, 0, 30));
}

trace::Trace trace_around(const Scene& scene, const FillOptions& options, int x, int y,
                          TraceLevel level) {
  trace::TraceFilter filter;
  filter.level = level;
  filter.triangles = trace::IndexSet::of(faces_around(scene, x, y, snap_margin(options)));
  return trace::record_scene(scene, options, filter);
}

std::vector<int> faces_around(const Scene& scene, int x, int y, double margin) {
  std::vector<int> out;
  const double px = x, py = y;
  for (int f = 0; f < static_cast<int>(scene.faces.size()); ++f) {
    const auto& v = scene.faces[f];
    const Vec2 a = scene.vertices[v[0]], b = scene.vertices[v[1]], c = scene.vertices[v[2]];
    if (px < std::min({a.x, b.x, c.x}) - margin || px > std::max({a.x, b.x, c.x}) + margin ||
        py < std::min({a.y, b.y, c.y}) - margin || py > std::max({a.y, b.y, c.y}) + margin)
      continue;
    out.push_back(f);
  }
  return out;
}

}  // namespace scantrace::grade
