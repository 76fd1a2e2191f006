#pragma once
// Test scenes of overlapping triangles (the band render's and the near-to-far render's tests).
#include <cstdint>

#include "src/scene.hpp"
#include "src/splitmix64.hpp"

namespace sttest {

// Overlapping triangles of every size at random depths, some far off the canvas, some crossing
// many bands, some thinner than a row: the cases where a band's clipping could differ from the
// canvas's.
inline scantrace::Scene overlapping_scene(std::uint64_t seed, int width, int height, int faces) {
  scantrace::SplitMix64 rng(seed);
  scantrace::Scene s;
  s.width = width;
  s.height = height;
  s.background = {1, 1, 1};
  for (int f = 0; f < faces; ++f) {
    const double cx = rng.uniform(-50, width + 50), cy = rng.uniform(-50, height + 50);
    const double size = f % 50 == 0 ? 1e6 : rng.uniform(0.3, 120);
    for (int k = 0; k < 3; ++k) {
      s.vertices.push_back({cx + rng.uniform(-size, size), cy + rng.uniform(-size, size)});
      s.vcolors.push_back({rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)});
      s.depth.push_back(rng.uniform(0, 10));
    }
    s.faces.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  }
  return s;
}

}  // namespace sttest
