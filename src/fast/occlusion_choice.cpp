#include "occlusion_choice.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace scantrace {

double estimated_overdraw(const Scene& scene, std::vector<float>& cells) {
  constexpr int kShift = 5, kCell = 1 << kShift;
  const int w = scene.width, h = scene.height;
  const int gw = (w + kCell - 1) >> kShift, gh = (h + kCell - 1) >> kShift;
  if (gw <= 0 || gh <= 0) return 1;
  cells.assign(static_cast<std::size_t>(gw) * gh, 0.f);
  // The centroid's cell from the sum of the three coordinates: one multiply, no division.
  constexpr double kThirdCell = 1.0 / (3 * kCell);
  double paint = 0;
  for (const auto& f : scene.faces) {
    const Vec2 a = scene.vertices[f[0]], b = scene.vertices[f[1]], c = scene.vertices[f[2]];
    const double area = 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
    const double x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
    const double y0 = std::min({a.y, b.y, c.y}), y1 = std::max({a.y, b.y, c.y});
    if (x1 - x0 <= kCell && y1 - y0 <= kCell) {
      // Most faces: small, counted whole where their centroid is (off the canvas: not at all).
      const double gx = (a.x + b.x + c.x) * kThirdCell, gy = (a.y + b.y + c.y) * kThirdCell;
      if (!(gx >= 0 && gy >= 0 && gx < gw && gy < gh)) continue;
      cells[static_cast<std::size_t>(gy) * gw + static_cast<std::size_t>(gx)] +=
          static_cast<float>(area);
      paint += area;
      continue;
    }
    // A large face: its area spread evenly over its box, of which the canvas's part counts.
    const double bx0 = std::max(x0, 0.0), bx1 = std::min(x1, double(w));
    const double by0 = std::max(y0, 0.0), by1 = std::min(y1, double(h));
    if (!(bx0 < bx1 && by0 < by1) || area == 0) continue;
    const double density = area / ((x1 - x0) * (y1 - y0));
    const int cx0 = static_cast<int>(bx0) >> kShift, cx1 = std::min(gw - 1, int(bx1) >> kShift);
    const int cy0 = static_cast<int>(by0) >> kShift, cy1 = std::min(gh - 1, int(by1) >> kShift);
    for (int cy = cy0; cy <= cy1; ++cy) {
      const double wy = std::min(by1, double((cy + 1) * kCell)) - std::max(by0, double(cy * kCell));
      for (int cx = cx0; cx <= cx1; ++cx) {
        const double wx =
            std::min(bx1, double((cx + 1) * kCell)) - std::max(bx0, double(cx * kCell));
        cells[static_cast<std::size_t>(cy) * gw + cx] += static_cast<float>(density * wx * wy);
      }
    }
    paint += density * (bx1 - bx0) * (by1 - by0);
  }
  double covered = 0;
  for (int cy = 0; cy < gh; ++cy)
    for (int cx = 0; cx < gw; ++cx) {
      const double cell_area =
          double(std::min(kCell, w - cx * kCell)) * std::min(kCell, h - cy * kCell);
      covered += std::min(cell_area, double(cells[static_cast<std::size_t>(cy) * gw + cx]));
    }
  return covered > 0 ? paint / covered : 1;
}

bool forms_surfaces(const Scene& scene) {
  // Three faces per vertex or more: a vertex count at most the face count (a closed triangle
  // mesh has about half as many vertices as faces, a soup three times as many).
  return !scene.faces.empty() && scene.vertices.size() <= scene.faces.size();
}

Occlusion choose_occlusion(const Scene& scene, const FillOptions& opt, std::vector<float>& cells) {
  if (opt.occlusion != Occlusion::automatic) return opt.occlusion;
  if (opt.visibility == Visibility::zbuffer &&
      static_cast<long long>(scene.width) * scene.height > 512LL * 512)
    return Occlusion::far_to_near;
  const bool near = forms_surfaces(scene) &&
                    estimated_overdraw(scene, cells) >= near_to_far_overdraw(opt.shading);
  return near ? Occlusion::near_to_far : Occlusion::far_to_near;
}

}  // namespace scantrace
