#include "viz/view_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace scantrace::viz {

ViewGeometry::ViewGeometry(Rect view, PixelBox region, double max_cell) : view_(view) {
  if (region.empty()) region = {0, 0, 0, 0};
  const double w = static_cast<double>(region.width()), h = static_cast<double>(region.height());
  cell_ = std::min({view.width / w, view.height / h, max_cell});
  if (cell_ >= 4) cell_ = std::floor(cell_);
  const double cx = (static_cast<double>(region.x0) + static_cast<double>(region.x1)) / 2;
  const double cy = (static_cast<double>(region.y0) + static_cast<double>(region.y1)) / 2;
  left_ = cx - view.width / (2 * cell_);
  top_ = cy - view.height / (2 * cell_);
  if (cell_ >= 4) {
    // Put cell borders (x - 0.5) on whole frame pixels.
    left_ = std::round((left_ + 0.5) * cell_) / cell_ - 0.5;
    top_ = std::round((top_ + 0.5) * cell_) / cell_ - 0.5;
  }
}

Point2d ViewGeometry::to_frame(double x, double y) const {
  return {view_.x + (x - left_) * cell_, view_.y + (y - top_) * cell_};
}

std::int64_t ViewGeometry::pixel_x(int u) const {
  // The frame pixel's centre, in canvas coordinates, rounded to the nearest pixel centre.
  return static_cast<std::int64_t>(std::floor(left_ + (u - view_.x + 0.5) / cell_ + 0.5));
}

std::int64_t ViewGeometry::pixel_y(int v) const {
  return static_cast<std::int64_t>(std::floor(top_ + (v - view_.y + 0.5) / cell_ + 0.5));
}

PixelBox ViewGeometry::visible() const {
  return {pixel_x(view_.x), pixel_y(view_.y), pixel_x(view_.x + view_.width - 1),
          pixel_y(view_.y + view_.height - 1)};
}

std::optional<std::pair<Point2d, Point2d>> clip_segment(Point2d p, Point2d q, const Rect2d& r) {
  const double dx = q.x - p.x, dy = q.y - p.y;
  double t0 = 0, t1 = 1;
  const double ps[4] = {-dx, dx, -dy, dy};
  const double qs[4] = {p.x - r.x, r.x + r.width - p.x, p.y - r.y, r.y + r.height - p.y};
  for (int i = 0; i < 4; ++i) {
    if (ps[i] == 0) {
      if (qs[i] < 0) return std::nullopt;
      continue;
    }
    const double t = qs[i] / ps[i];
    if (ps[i] < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 > t1) return std::nullopt;
  }
  return std::make_pair(Point2d{p.x + t0 * dx, p.y + t0 * dy},
                        Point2d{p.x + t1 * dx, p.y + t1 * dy});
}

namespace {
constexpr int kShift = 4;  // cv::line's fixed-point bits: positions to 1/16 pixel

Point fixed_point(Point2d p) {
  return {static_cast<int>(std::lround(p.x * (1 << kShift))),
          static_cast<int>(std::lround(p.y * (1 << kShift)))};
}
}  // namespace

void draw_segment(FrameView& image, Point2d p, Point2d q, const Rect& clip, const Scalar& colour,
                  int thickness, std::optional<Mark> mark) {
  // Pixel centres of the frame are at integer positions; the clip box reaches half a pixel out.
  const Rect2d box{clip.x - 0.5, clip.y - 0.5, static_cast<double>(clip.width),
                   static_cast<double>(clip.height)};
  const auto inside = clip_segment(p, q, box);
  if (!inside) return;
  // Drawn in the view's own area, as OpenCV drew it into a region of interest.
  FrameView roi = image(clip);
  const Point2d o(clip.x, clip.y);
  roi.line(fixed_point(inside->first - o), fixed_point(inside->second - o), colour, thickness,
           LINE_AA, kShift, std::move(mark));
}

void draw_segment_with_halo(FrameView& image, Point2d p, Point2d q, const Rect& clip,
                            const Scalar& colour, int thickness, const Scalar& halo, int halo_width,
                            std::optional<Mark> mark) {
  draw_segment(image, p, q, clip, halo, thickness + 2 * halo_width);
  draw_segment(image, p, q, clip, colour, thickness, std::move(mark));
}

}  // namespace scantrace::viz
