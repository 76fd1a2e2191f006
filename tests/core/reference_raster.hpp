#pragma once
// The tests' names for the library's exact reference (src/exact_reference.hpp): a brute-force
// rasterizer that shares no code with the scanline fill, so agreement between the two is evidence
// rather than a tautology. The tests compare on the fill's own grid (1/256 px by default).
#include <span>

#include "reference/exact_reference.hpp"

namespace sttest {

using i64 = scantrace::reference::i64;
using i128 = scantrace::reference::i128;
using RefRule = scantrace::FillRule;
using RefPolygon = scantrace::reference::Polygon;
using RefRaster = scantrace::reference::Raster;
using scantrace::reference::ceil_div;
using scantrace::reference::floor_div;
using scantrace::reference::GridPt;
using scantrace::reference::mean_color;

inline i64 ref_snap(double v, int bits) { return scantrace::reference::snap(v, bits); }
inline GridPt ref_snap(scantrace::Vec2 p, int bits) { return scantrace::reference::snap(p, bits); }

inline RefRaster ref_rasterize(int width, int height, std::span<const scantrace::Vec2> points,
                               std::span<const scantrace::Color> colors, RefRule rule,
                               int bits = scantrace::kDefaultSubpixelBits) {
  return scantrace::reference::rasterize(width, height, points, colors, rule, bits);
}

}  // namespace sttest
