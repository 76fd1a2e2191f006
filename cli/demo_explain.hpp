#pragma once
// The demo's last step: the course triangle's trace, just written, explained as a page and a
// video. Two definitions, one per executable (cli/CMakeLists.txt):
// - scantrace-tools (cli/demo_explain_tools.cpp): the video (OpenCV's video I/O) and the trace
//   page when the web build made its player (cli/trace_page.hpp), else the page of WebP frames;
// - `scantrace` when scantrace-tools is not built, i.e. the demo's build, which installs no
//   OpenCV (cli/demo_explain_svg.cpp): the page of SVG frames (viz/step_page.hpp), and a line
//   saying how to make the video.
// Why not one: OpenCV and its 300 Debian packages are two thirds of a fresh machine's wait for
// the demo (docs/performance.md, "Building"); the display list draws the page without them.
#include <filesystem>

namespace scantrace::cli {

// Throws std::runtime_error naming the file when the trace cannot be read or an output written.
void explain_demo_triangle(const std::filesystem::path& trace_file,
                           const std::filesystem::path& video, const std::filesystem::path& page);

}  // namespace scantrace::cli
