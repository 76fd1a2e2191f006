#include "stress/stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scantrace::stress {

int to_byte(double c) {
  if (std::isnan(c)) return 0;
  return static_cast<int>(std::clamp(std::round(255.0 * c), 0.0, 255.0));
}

void ColourError::add(double got, double want) {
  // A non-finite colour has an infinite error (and is counted as NaN/Inf by the checks).
  const double e =
      std::isfinite(got) ? std::abs(got - want) : std::numeric_limits<double>::infinity();
  max = std::max(max, e);
  sum_sq += e * e;
  ++samples;
  const int e8 = std::abs(to_byte(got) - to_byte(want));
  max8 = std::max(max8, e8);
  sum_sq8 += static_cast<double>(e8) * e8;
}

void ColourError::merge(const ColourError& o) {
  max = std::max(max, o.max);
  sum_sq += o.sum_sq;
  samples += o.samples;
  max8 = std::max(max8, o.max8);
  sum_sq8 += o.sum_sq8;
}

double ColourError::rms() const {
  return samples ? std::sqrt(sum_sq / static_cast<double>(samples)) : 0.0;
}
double ColourError::rms8() const {
  return samples ? std::sqrt(sum_sq8 / static_cast<double>(samples)) : 0.0;
}

void CellStats::add(const CaseResult& r, long long triangles_in_case, double colour_tolerance) {
  ++cases;
  triangles += triangles_in_case;
  fills += r.fills;
  ref_pixels += r.ref_pixels;
  missing += r.missing;
  extra += r.extra;
  gaps += r.gaps;
  overlaps += r.overlaps;
  nonfinite += r.nonfinite;
  order_diffs += r.order_differs ? 1 : 0;
  colour.merge(r.colour);
  fill_seconds += r.fill_seconds;
  if (r.failed(colour_tolerance)) ++failing_cases;
}

}  // namespace scantrace::stress
