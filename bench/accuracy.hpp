#pragma once
// The error of a rasterizer on a scene: every face, its vertices on the fill's 1/256 px grid,
// filled alone (in all 6 vertex orders) and compared pixel by pixel with the exact reference
// (src/exact_reference.hpp) by the stress checks.
#include "src/scene.hpp"
#include "stress/rasterizer.hpp"

namespace scantrace::bench {

struct Accuracy {
  long long reference_pixels = 0;  // pixels the reference covers, over all fills
  long long wrong_pixels = 0;      // missing + extra + overlapping + non-finite
  double colour_max = 0;           // largest channel error of a Gouraud pixel (0 when flat-only)
  bool shades = false;
  double wrong_per_million() const {
    return reference_pixels ? 1e6 * static_cast<double>(wrong_pixels) / reference_pixels : 0;
  }
};

Accuracy measure_accuracy(stress::Rasterizer& rasterizer, const Scene& scene);

}  // namespace scantrace::bench
