#pragma once
// The `step` window's overlays (viz/step_overlay.hpp) drawn onto OpenCV images: the same display
// lists, drawn over the frame by the OpenCV backend.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "viz/step_overlay.hpp"

namespace scantrace::viz {

void mark_pixel(cv::Mat& frame, const ViewGeometry& g, CanvasPixel pixel);
void draw_history_box(cv::Mat& frame, const Rect& area, const Typography& type,
                      const std::vector<std::string>& lines);
void draw_key_help(cv::Mat& frame, const Typography& type, const std::vector<std::string>& lines);
cv::Mat status_strip(int width, int height, const Typography& type, const std::string& left,
                     const std::string& right);

}  // namespace scantrace::viz
