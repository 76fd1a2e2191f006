#pragma once
// The regions of an explanatory frame (docs/design.md §6): a title bar across the top, the magnified
// canvas on the left, the side panel on the right.
#include <opencv2/core.hpp>

#include "viz/typography.hpp"

namespace scantrace::viz {

struct FrameLayout {
  cv::Size frame;
  cv::Rect title_bar;
  cv::Rect view;   // the magnified canvas
  cv::Rect panel;  // tables, colours, formula, legend
  int margin = 0;

  static FrameLayout for_frame(cv::Size frame, const Typography& type);
};

}  // namespace scantrace::viz
