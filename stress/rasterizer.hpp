#pragma once
// What the stress runner measures: anything that fills triangles into a StressCanvas. The four
// methods of the library are built in (make_method); a rasterizer outside src/ (OpenCV's
// fillConvexPoly, adapted in cli/) implements the same interface, so it is measured on the same
// cases by the same checks.
#include <memory>
#include <string>

#include "src/fill_options.hpp"
#include "stress/stress_canvas.hpp"
#include "stress/stress_case.hpp"

namespace scantrace::stress {

class Rasterizer {
 public:
  virtual ~Rasterizer() = default;

  virtual std::string name() const = 0;
  // The rule its coverage is compared under (the reference is computed for this rule).
  virtual FillRule rule() const = 0;
  // Whether it interpolates Gouraud colours worth checking against the exact barycentric colour
  // (false for a flat-only rasterizer).
  virtual bool shades() const = 0;

  // Called before the triangles of one image are drawn: `canvas` is cleared and of the case's size.
  virtual void begin(StressCanvas& canvas) { (void)canvas; }
  // Fills one triangle (the only part that is timed). `bits`: the case's subpixel grid.
  virtual void draw(StressCanvas& canvas, const Triangle& t, int bits, Shading shading) = 0;
  // Moves what draw() produced into `canvas`, for rasterizers that draw elsewhere (untimed).
  virtual void collect(StressCanvas& canvas, const Triangle& t) {
    (void)canvas;
    (void)t;
  }
};

// The library's fill with method `m` under the top-left rule.
std::unique_ptr<Rasterizer> make_method(Method m);

}  // namespace scantrace::stress
