#include "stress/opencv_rasterizer.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace scantrace::stress {
namespace {

// Fractional bits of the vertices passed to OpenCV (see the header).
constexpr int kShift = 8;

class OpenCvRasterizer final : public Rasterizer {
 public:
  std::string name() const override { return "opencv"; }
  FillRule rule() const override { return FillRule::closed; }
  bool shades() const override { return false; }  // fillConvexPoly has no Gouraud shading

  void begin(stress::StressCanvas& canvas) override {
    image_.create(canvas.height(), canvas.width(), CV_8UC3);
    image_.setTo(cv::Scalar::all(0));
  }

  void draw(stress::StressCanvas&, const stress::Triangle& t, int, Shading) override {
    for (int i = 0; i < 3; ++i)
      points_[i] = {cv::saturate_cast<int>(std::ldexp(t.v[i].x, kShift)),
                    cv::saturate_cast<int>(std::ldexp(t.v[i].y, kShift))};
    cv::fillConvexPoly(image_, points_.data(), 3, cv::Scalar::all(255), cv::LINE_8, kShift);
  }

  // Reads back the pixels it wrote around the triangle, into the counting canvas, and clears
  // them. fillConvexPoly writes only between its outline and the rows and columns of the rounded
  // vertices, so their bounding box with a margin of 2 px holds every write; scanning just that
  // keeps a 1,000-triangle mesh from costing 1,000 scans of the whole image.
  void collect(stress::StressCanvas& canvas, const stress::Triangle& t) override {
    const double s = std::ldexp(1.0, -kShift);
    double x0 = points_[0].x, x1 = x0, y0 = points_[0].y, y1 = y0;
    for (const cv::Point& p : points_) {
      x0 = std::min<double>(x0, p.x), x1 = std::max<double>(x1, p.x);
      y0 = std::min<double>(y0, p.y), y1 = std::max<double>(y1, p.y);
    }
    const auto clip = [](double v, int size) {
      return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(size)));
    };
    const int cx0 = clip(std::floor(x0 * s) - 2, image_.cols);
    const int cx1 = clip(std::ceil(x1 * s) + 3, image_.cols);
    const int cy0 = clip(std::floor(y0 * s) - 2, image_.rows);
    const int cy1 = clip(std::ceil(y1 * s) + 3, image_.rows);
    const Color flat = (t.c[0] + t.c[1] + t.c[2]) * (1.0 / 3.0);
    for (int y = cy0; y < cy1; ++y) {
      cv::Vec3b* row = image_.ptr<cv::Vec3b>(y);
      for (int x = cx0; x < cx1; ++x) {
        if (row[x] == cv::Vec3b(0, 0, 0)) continue;
        canvas.set(x, y, flat);
        row[x] = cv::Vec3b(0, 0, 0);
      }
    }
  }

 private:
  cv::Mat image_;
  std::array<cv::Point, 3> points_;
};

}  // namespace

std::unique_ptr<Rasterizer> make_opencv_rasterizer() {
  return std::make_unique<OpenCvRasterizer>();
}

}  // namespace scantrace::stress
