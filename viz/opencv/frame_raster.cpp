#include "viz/opencv/frame_raster.hpp"

#include <cstring>

#include <opencv2/imgproc.hpp>

namespace scantrace::viz {
namespace {

cv::Scalar cv_scalar(const Scalar& s) {
  return {s[0], s[1], s[2], s[3]};
}

int cv_line(LineType t) {
  return static_cast<int>(t);
}

struct Draw {
  cv::Mat& m;
  void operator()(const RectOp& r) const {
    cv::rectangle(m, cv::Rect(r.rect), cv_scalar(r.colour), r.thickness, cv_line(r.type));
  }
  void operator()(const LineOp& l) const {
    cv::line(m, cv::Point(l.a), cv::Point(l.b), cv_scalar(l.colour), l.thickness, cv_line(l.type),
             l.shift);
  }
  void operator()(const CircleOp& c) const {
    cv::circle(m, cv::Point(c.centre), c.radius, cv_scalar(c.colour), c.thickness, cv_line(c.type));
  }
  void operator()(const TextOp& t) const {
    cv::putText(m, t.text, cv::Point(t.origin), static_cast<int>(t.font), t.scale,
                cv_scalar(t.colour), t.thickness, cv_line(t.type));
  }
  void operator()(const PixelsOp& p) const {
    // The block, cropped to the image, row by row: both are packed 3-byte BGR pixels.
    static_assert(sizeof(Vec3b) == 3 && sizeof(cv::Vec3b) == 3);
    const cv::Rect inside = cv::Rect(p.area) & cv::Rect(0, 0, m.cols, m.rows);
    for (int y = inside.y; y < inside.y + inside.height; ++y) {
      const Vec3b* in = p.bgr->data() + static_cast<std::size_t>(y - p.area.y) * p.area.width +
                        (inside.x - p.area.x);
      std::memcpy(m.ptr<std::uint8_t>(y) + 3 * inside.x, in,
                  static_cast<std::size_t>(inside.width) * 3);
    }
  }
};

}  // namespace

void draw_ops(const Frame& frame, cv::Mat& image) {
  const cv::Rect whole(0, 0, image.cols, image.rows);
  for (const DrawOp& op : frame.ops()) {
    // A clipped op is drawn into the region of interest, as the composer once drew it.
    cv::Mat target = op.clip ? image(cv::Rect(*op.clip) & whole) : image;
    std::visit(Draw{target}, op.body);
  }
}

cv::Mat rasterize(const Frame& frame) {
  cv::Mat image(cv::Size(frame.size()), CV_8UC3, cv_scalar(frame.background()));
  draw_ops(frame, image);
  return image;
}

}  // namespace scantrace::viz
