#include "bench/accuracy.hpp"

#include <algorithm>

#include "stress/checks.hpp"
#include "stress/reference_window.hpp"

namespace scantrace::bench {

Accuracy measure_accuracy(stress::Rasterizer& rasterizer, const Scene& scene) {
  stress::Checker checker;
  const SubpixelGrid grid(kDefaultSubpixelBits);
  Accuracy a;
  a.shades = rasterizer.shades();
  stress::StressCase c;
  c.width = scene.width;
  c.height = scene.height;
  c.bits = kDefaultSubpixelBits;
  c.triangles.resize(1);
  for (const auto& face : scene.faces) {
    stress::Triangle& t = c.triangles[0];
    // The reference works on the input as given (a 2^-30 grid), the fill on its 1/256 px grid:
    // the vertices are put on the fill's grid first, so that both judge the same triangle and a
    // difference is an error of the method, not of the rounding of the input.
    for (int k = 0; k < 3; ++k)
      t.v[k] = grid.to_pixels(grid.snap(scene.vertices[face[k]])), t.c[k] = scene.vcolors[face[k]];
    const stress::ReferenceWindow ref(c.width, c.height, t.v, t.c, rasterizer.rule());
    const stress::CaseResult r = checker.check_triangle(rasterizer, c, ref);
    a.reference_pixels += r.ref_pixels;
    a.wrong_pixels += r.missing + r.extra + r.overlaps + r.nonfinite;
    if (a.shades) a.colour_max = std::max(a.colour_max, r.colour.max);
  }
  return a;
}

}  // namespace scantrace::bench
