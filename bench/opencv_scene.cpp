#include "bench/opencv_scene.hpp"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "src/image.hpp"
#include "src/painter.hpp"

namespace scantrace::bench {
namespace {
constexpr int kShift = 8;  // fractional bits of the vertices, as in stress/opencv_rasterizer.cpp
}

OpenCvScene::OpenCvScene(const Scene& scene) : scene_(scene) {
  for (const auto& face : scene.faces) {
    std::array<cv::Point, 3> p;
    Color mean;
    for (int k = 0; k < 3; ++k) {
      const Vec2 v = scene.vertices[face[k]];
      p[k] = {cv::saturate_cast<int>(std::ldexp(v.x, kShift)),
              cv::saturate_cast<int>(std::ldexp(v.y, kShift))};
      mean += scene.vcolors[face[k]];
    }
    const Bgr8 px = Bgr8::from(mean * (1.0 / 3.0));
    points_.push_back(p);
    colors_.push_back(cv::Scalar(px.b, px.g, px.r));
  }
}

void OpenCvScene::render(cv::Mat& image) const {
  image.create(scene_.height, scene_.width, CV_8UC3);
  const Bgr8 bg = Bgr8::from(scene_.background);
  image.setTo(cv::Scalar(bg.b, bg.g, bg.r));
  for (int f : painter_order(face_depths(scene_)))
    cv::fillConvexPoly(image, points_[f].data(), 3, colors_[f], cv::LINE_8, kShift);
}

}  // namespace scantrace::bench
