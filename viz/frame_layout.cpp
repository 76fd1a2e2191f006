#include "viz/frame_layout.hpp"

#include <algorithm>
#include <cmath>

namespace scantrace::viz {

FrameLayout FrameLayout::for_frame(Size frame, const Typography& type) {
  FrameLayout l;
  l.frame = frame;
  l.margin = type.px(12);
  const int bar = type.px(40);
  l.title_bar = {0, 0, frame.width, std::min(bar, frame.height)};
  // The panel's width follows its text (which scales with the frame) but never takes more than
  // half the frame, so the canvas stays the larger part even on narrow frames.
  const int panel_width =
      std::min(frame.width / 2, std::max(type.px(545), static_cast<int>(frame.width * 0.43)));
  const int top = l.title_bar.height + l.margin;
  const int height = std::max(1, frame.height - top - l.margin);
  l.panel = {frame.width - l.margin - panel_width, top, panel_width, height};
  l.view = {l.margin, top, std::max(1, l.panel.x - 2 * l.margin), height};
  return l;
}

}  // namespace scantrace::viz
