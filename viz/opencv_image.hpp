#pragma once
// The OpenCV boundary (docs/design.md §2): float RGB [0, 1] on our side, 8-bit BGR on OpenCV's.
// Frame and video code reuses these, so the conversion rule lives in one place.
#include <cstdint>

#include <opencv2/core.hpp>

#include "src/image.hpp"

namespace scantrace {

// A CV_8UC3 matrix in BGR order, the layout cv::imwrite and cv::VideoWriter expect.
cv::Mat to_bgr8(const RgbImage& image);

// The inverse for 8-bit BGR (CV_8UC3) matrices: each channel byte / 255, in RGB order.
RgbImage from_bgr8(const cv::Mat& bgr);

}  // namespace scantrace
