#pragma once
// A replay as one self-contained HTML page: every frame embedded as a compressed image, a step
// slider, buttons, the keys of `scantrace step`, play/pause, the list of steps, and an address
// that follows the step (OUT.html#step=37 opens at step 37). No network, no external script or
// font: the file can be mailed, opened from a USB stick, or put on any web server.
//
//   viz::Replayer r(trace, {}, {1280, 720}, "triangle.jsonl");
//   viz::write_html_player(r, 0, r.steps().size() - 1, "triangle.html", {});
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "viz/progress.hpp"
#include "viz/replayer.hpp"

namespace scantrace::viz {

struct HtmlPlayerOptions {
  std::string source = "the trace";  // how the page names its input
  double fps = 5;                    // play speed (steps per second)
};

struct HtmlPlayerResult {
  std::size_t steps = 0;
  std::size_t bytes = 0;  // of the page
  std::string format;     // of the embedded frames ("webp")
};

// Writes steps first..last (0-based, inclusive) of `replayer` to `out`, atomically. Throws
// std::runtime_error naming the file when a frame cannot be encoded or the file written.
HtmlPlayerResult write_html_player(Replayer& replayer, std::size_t first, std::size_t last,
                                   const std::filesystem::path& out,
                                   const HtmlPlayerOptions& options, Progress* progress = nullptr);

// One frame as the page embeds it: the image file's bytes and its MIME type.
struct EncodedFrame {
  std::vector<unsigned char> bytes;
  std::string mime;
};
EncodedFrame encode_page_frame(const cv::Mat& frame);

// Standard base64 (RFC 4648, with padding), as data: URLs need it.
std::string base64(const std::vector<unsigned char>& bytes);

}  // namespace scantrace::viz
