#pragma once
// A Scene drawn by OpenCV's cv::fillConvexPoly, flat only (it has no Gouraud shading): the same
// faces in the same painter's order on the same 8-bit, 3-channel image. Vertices are converted
// to cv::Point with 8 fractional bits once, outside the timing, as an OpenCV user would hold
// them; the painter's sort and the clear are timed, as they are in our render.
#include <array>
#include <vector>

#include <opencv2/core.hpp>

#include "src/scene.hpp"

namespace scantrace::bench {

class OpenCvScene {
 public:
  explicit OpenCvScene(const Scene& scene);
  // Clears `image` to the background and draws every face; returns the faces drawn.
  void render(cv::Mat& image) const;

 private:
  const Scene& scene_;
  std::vector<std::array<cv::Point, 3>> points_;
  std::vector<cv::Scalar> colors_;  // the flat colour (mean of the vertex colours), 8-bit BGR
};

}  // namespace scantrace::bench
