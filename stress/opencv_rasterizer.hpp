#pragma once
// OpenCV's cv::fillConvexPoly as a stress rasterizer, measured on the same cases as the library's
// methods (docs/accuracy.md). A library of its own (scantrace_stress_opencv), so that the stress
// generator itself stays standard library only.
#include <memory>

#include "stress/rasterizer.hpp"

namespace scantrace::stress {

// Flat fills of an 8-bit, 3-channel image (OpenCV's usual target), compared under the closed
// rule, OpenCV's own. Vertices are passed the way an OpenCV user passes subpixel positions: in 8
// fractional bits, cv::Point(round(256 v)) with shift = 8, saturated to int (cv::saturate_cast).
// That is exact for every vertex on a grid of up to 8 bits (finer ones are rounded to 1/256 px)
// and clamps coordinates beyond ±2^31 / 256 ≈ ±8.4e6 px — where OpenCV loses pixels. The clamp
// also bounds OpenCV's cost: fillConvexPoly steps through every row from the top vertex down, on
// the canvas or not, so a vertex at y = −1e9 passed unclamped would cost a billion empty rows.
std::unique_ptr<Rasterizer> make_opencv_rasterizer();

}  // namespace scantrace::stress
