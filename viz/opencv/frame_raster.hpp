#pragma once
// The OpenCV backend of the display list (docs/design.md §6): a viz::Frame drawn into an 8-bit
// BGR image by the OpenCV calls each operation records, in order — the raster of PNG frames, the
// MP4 and the `step` window.
#include <opencv2/core.hpp>

#include "viz/frame.hpp"

namespace scantrace::viz {

// A new CV_8UC3 image of the frame's size, filled with its background, with every op drawn.
cv::Mat rasterize(const Frame& frame);
// Draws the frame's ops over `image` (CV_8UC3; the background is not painted).
void draw_ops(const Frame& frame, cv::Mat& image);

}  // namespace scantrace::viz
