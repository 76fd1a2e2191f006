#pragma once
// One generated test case: a canvas, a subpixel grid, and either one triangle or a mesh of
// triangles that tiles a known region. A case is a pure function of (family, seed, index), so a
// failure is replayed from those three numbers alone.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "src/color.hpp"
#include "stress/families.hpp"
#include "src/vec2.hpp"

namespace scantrace::stress {

struct Triangle {
  std::array<Vec2, 3> v;
  std::array<Color, 3> c;
};

struct StressCase {
  Family family = Family::random;
  std::uint64_t seed = 0;
  std::uint64_t index = 0;
  int width = 512, height = 512;
  int bits = 8;      // subpixel bits of the fill; every vertex is on this grid
  std::string kind;  // the variant within the family, for reports ("fan", "vertical", …)
  std::vector<Triangle> triangles;  // one for the triangle families, many for meshes
  // Meshes only: the polygon the triangles tile exactly (a rectangle), so that under the fill rule
  // every pixel it owns must be written exactly once and no other pixel at all.
  std::vector<Vec2> region;

  bool is_mesh() const { return !region.empty(); }
};

// Case `index` of `family` under `seed` (deterministic on every platform).
StressCase generate(Family family, std::uint64_t seed, std::uint64_t index);

}  // namespace scantrace::stress
