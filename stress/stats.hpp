#pragma once
// What the checks count, per case and summed per (family, method) cell of the report.
#include <cstdint>
#include <string>
#include <vector>

#include "stress/families.hpp"

namespace scantrace::stress {

// Colour error against the exact barycentric colour, per channel: at the float level and at the
// 8-bit level of the image files, |round(255 c) − round(255 c_ref)| (docs/design.md §2).
struct ColourError {
  double max = 0, sum_sq = 0;
  long long samples = 0;  // channels compared
  int max8 = 0;
  double sum_sq8 = 0;

  void add(double got, double want);
  void merge(const ColourError& o);
  double rms() const;
  double rms8() const;
};

// The 8-bit value of a channel as the image files store it: round(255 c), clamped; NaN → 0.
int to_byte(double c);

struct CaseResult {
  long long fills = 0;         // triangle fills (each triangle in each of the 6 vertex orders)
  long long ref_pixels = 0;    // pixels the reference covers, summed over the fills
  long long missing = 0;       // covered by the reference, not written
  long long extra = 0;         // written, not covered (meshes: outside the tiled region)
  long long gaps = 0;          // meshes: pixels of the region written by no triangle
  long long overlaps = 0;      // pixels written more than once (by a mesh, or by one triangle)
  long long nonfinite = 0;     // pixels written with a NaN or infinite channel
  bool order_differs = false;  // the images of the 6 vertex orders are not all identical
  ColourError colour;
  double fill_seconds = 0;
  // The first problem met, for the reproducer ("" when none) and the order it was met in.
  std::string problem;
  int problem_order = 0;

  bool failed(double colour_tolerance) const {
    return missing + extra + gaps + overlaps + nonfinite > 0 || order_differs ||
           colour.max > colour_tolerance;
  }
};

struct CellStats {
  Family family = Family::random;
  std::string method;
  bool mesh = false;    // gaps counted instead of missing pixels, no colour check
  bool shades = false;  // colours checked
  long long cases = 0, triangles = 0, fills = 0, ref_pixels = 0;
  long long missing = 0, extra = 0, gaps = 0, overlaps = 0, nonfinite = 0;
  long long order_diffs = 0;    // cases whose images differ between vertex orders
  long long failing_cases = 0;  // cases with any problem
  ColourError colour;
  double fill_seconds = 0;
  std::vector<std::string> reproducers;  // the first few failing cases, one line each

  void add(const CaseResult& r, long long triangles_in_case, double colour_tolerance);
  bool failed(double colour_tolerance) const {
    return failing_cases > 0 || colour.max > colour_tolerance;
  }
};

}  // namespace scantrace::stress
