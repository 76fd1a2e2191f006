#include "viz/opencv/step_overlay_raster.hpp"

#include "viz/opencv/frame_raster.hpp"

namespace scantrace::viz {
namespace {

// Composes with `draw` on an empty display list the image's size, then draws it over the image.
template <class F>
void over(cv::Mat& image, F&& draw) {
  Frame frame(Size(image.cols, image.rows), Scalar{});
  FrameView view(frame);
  draw(view);
  draw_ops(frame, image);
}

}  // namespace

void mark_pixel(cv::Mat& frame, const ViewGeometry& g, CanvasPixel pixel) {
  over(frame, [&](FrameView& v) { mark_pixel(v, g, pixel); });
}

void draw_history_box(cv::Mat& frame, const Rect& area, const Typography& type,
                      const std::vector<std::string>& lines) {
  over(frame, [&](FrameView& v) { draw_history_box(v, area, type, lines); });
}

void draw_key_help(cv::Mat& frame, const Typography& type, const std::vector<std::string>& lines) {
  over(frame, [&](FrameView& v) { draw_key_help(v, type, lines); });
}

cv::Mat status_strip(int width, int height, const Typography& type, const std::string& left,
                     const std::string& right) {
  return rasterize(compose_status_strip(width, height, type, left, right));
}

}  // namespace scantrace::viz
