#include "viz/opencv_image.hpp"

#include <cmath>
#include <stdexcept>

namespace scantrace {

cv::Mat to_bgr8(const RgbImage& image) {
  cv::Mat bgr(image.height(), image.width(), CV_8UC3);
  for (int y = 0; y < image.height(); ++y) {
    const Rgb32f* in = image.row(y);
    auto* out = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < image.width(); ++x)
      out[x] = cv::Vec3b(to_byte(in[x].b), to_byte(in[x].g), to_byte(in[x].r));
  }
  return bgr;
}

RgbImage from_bgr8(const cv::Mat& bgr) {
  if (bgr.type() != CV_8UC3) throw std::invalid_argument("from_bgr8: expected a CV_8UC3 matrix");
  RgbImage image(bgr.cols, bgr.rows);
  for (int y = 0; y < bgr.rows; ++y) {
    const auto* in = bgr.ptr<cv::Vec3b>(y);
    Rgb32f* out = image.row(y);
    for (int x = 0; x < bgr.cols; ++x)
      out[x] = {in[x][2] / 255.0f, in[x][1] / 255.0f, in[x][0] / 255.0f};
  }
  return image;
}

}  // namespace scantrace
