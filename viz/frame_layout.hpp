#pragma once
// The regions of an explanatory frame (docs/design.md §6): a title bar across the top, the
// magnified canvas on the left, the side panel on the right.
#include "viz/frame.hpp"

#include "viz/typography.hpp"

namespace scantrace::viz {

struct FrameLayout {
  Size frame;
  Rect title_bar;
  Rect view;   // the magnified canvas
  Rect panel;  // tables, colours, formula, legend
  int margin = 0;

  static FrameLayout for_frame(Size frame, const Typography& type);
};

}  // namespace scantrace::viz
