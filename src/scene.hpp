#pragma once
// The course's scene: shared vertex arrays and triangles indexing them (keys of the scene file:
// vertices, vcolors, faces, depth, and optional width, height, background).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "color.hpp"
#include "vec2.hpp"

namespace scantrace {

inline constexpr int kDefaultCanvasSize = 512;
// A canvas larger than this (in pixels) is refused before anything is allocated: 2^28 pixels is
// 3 GiB as a float RGB canvas.
inline constexpr long long kMaxCanvasPixels = 1LL << 28;

struct Scene {
  std::vector<Vec2> vertices;             // [x, y]: x = column, y = row (pointing down)
  std::vector<Color> vcolors;             // one RGB colour per vertex, in [0, 1]
  std::vector<std::array<int, 3>> faces;  // 0-based vertex indices
  std::vector<double> depth;              // one depth per vertex (larger = farther)
  int width = kDefaultCanvasSize;
  int height = kDefaultCanvasSize;
  Color background{1, 1, 1};
};

// One face's three corners as the fill takes them: positions and colours, in face order. The one
// place a face is gathered from the scene's shared arrays (renders, bands, benchmarks).
struct FaceCorners {
  std::array<Vec2, 3> points;
  std::array<Color, 3> colors;
};

inline FaceCorners corners_of(const Scene& scene, const std::array<int, 3>& face) {
  return {{scene.vertices[face[0]], scene.vertices[face[1]], scene.vertices[face[2]]},
          {scene.vcolors[face[0]], scene.vcolors[face[1]], scene.vcolors[face[2]]}};
}

// The corners' depths (z-buffer renders).
inline std::array<double, 3> corner_depths(const Scene& scene, const std::array<int, 3>& face) {
  return {scene.depth[face[0]], scene.depth[face[1]], scene.depth[face[2]]};
}

// The first problem found in a scene, naming the element, e.g. {"faces[812]", "index 5012 is out
// of range (4999 vertices)"}.
struct SceneProblem {
  std::string element;
  std::string problem;
};

std::optional<SceneProblem> validate(const Scene& scene);

}  // namespace scantrace
