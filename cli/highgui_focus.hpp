#pragma once
// HighGUI's Qt backend shows the image in a scroll view that takes the keyboard focus when it is
// clicked, and from then on keeps the arrow and page keys for scrolling: they never reach
// cv::waitKeyEx. `scantrace step` is driven by those keys and by clicks on pixels, so it takes
// the focus away from such views. Without Qt (another HighGUI backend) this does nothing.
namespace scantrace::cli {

// Call after the window exists (cv::namedWindow).
void keep_keys_with_window();

}  // namespace scantrace::cli
