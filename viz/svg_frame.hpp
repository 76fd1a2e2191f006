#pragma once
// The SVG backend of the display list (docs/design.md §6): one frame as a self-contained SVG 1.1
// document — no external reference, no font: text is drawn as the Hershey strokes OpenCV draws
// (viz/hershey.hpp), so every label has the extent the layout measured. The magnified canvas
// cells (a PixelsOp) are one embedded PNG image each, drawn unsmoothed.
//
// Coordinates: OpenCV puts a pixel's centre on integer coordinates, SVG its corner, so every
// stroke is drawn half a pixel right and down of its OpenCV numbers and every filled area over the
// pixels OpenCV fills; lines keep their width, with round caps as OpenCV's thick lines have.
#include <string>

#include "viz/frame.hpp"

namespace scantrace::viz {

std::string to_svg(const Frame& frame);

}  // namespace scantrace::viz
