#pragma once
// The demo's last step: the course triangle's trace, just written, explained as a page and a
// video. Two explanations, one per executable that runs `demo`, each handed to
// add_demo_command (cli/commands.hpp) by its main():
// - scantrace-tools (cli/demo_explain_tools.cpp): the video (OpenCV's video I/O) and the trace
//   page when the web build made its player (cli/trace_page.hpp), else the page of WebP frames;
// - `scantrace` when scantrace-tools is not built, i.e. the demo's build, which installs no
//   OpenCV (cli/demo_explain_svg.cpp): the page of SVG frames (viz/step_page.hpp), and a line
//   saying how to make the video.
// Why not one: OpenCV and its 300 Debian packages are two thirds of a fresh machine's wait for
// the demo (docs/performance.md, "Building"); the display list draws the page without them.
// Why a parameter rather than one symbol defined twice: the main app's objects hold `demo`, and
// every executable linking them (scantrace-diff, the tests) would have to define a symbol it
// never calls, with the libraries that definition needs.
#include <filesystem>

namespace scantrace::cli {

// Each throws std::runtime_error naming the file when the trace cannot be read or an output
// written.
using ExplainDemo = void (*)(const std::filesystem::path& trace_file,
                             const std::filesystem::path& video, const std::filesystem::path& page);
void explain_demo_with_svg(const std::filesystem::path& trace_file,
                           const std::filesystem::path& video, const std::filesystem::path& page);
void explain_demo_with_video(const std::filesystem::path& trace_file,
                             const std::filesystem::path& video, const std::filesystem::path& page);

}  // namespace scantrace::cli
