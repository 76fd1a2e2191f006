#pragma once
// A replay as one self-contained HTML page: every step's frame embedded, a step slider, buttons,
// the keys of `scantrace step`, play/pause, the list of steps, and an address that follows the
// step (OUT.html#step=37 opens at step 37). No network, no external script or font: the file can
// be mailed, opened from a USB stick, or put on any web server.
//
// The page does not care how a frame was drawn: the caller encodes each step (`EncodeStep`).
// Two encoders exist: raster frames as lossless WebP through OpenCV (viz/html_player.hpp), and
// the display list as SVG, gzipped, here (write_svg_step_page) — the page the `scantrace` command
// writes without OpenCV (`scantrace demo` in the demo's build), sharp at any zoom.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "viz/frame_sequence.hpp"
#include "viz/progress.hpp"

namespace scantrace::viz {

struct HtmlPlayerOptions {
  std::string source = "the trace";  // how the page names its input
  double fps = 5;                    // play speed (steps per second)
};

struct HtmlPlayerResult {
  std::size_t steps = 0;
  std::size_t bytes = 0;  // of the page
  std::string format;     // of the embedded frames ("webp", "svg")
};

// One frame as the page embeds it: the image file's bytes and its MIME type; `gzipped` when the
// bytes are that file gzipped (the page inflates them with DecompressionStream when shown).
struct EncodedFrame {
  std::vector<unsigned char> bytes;
  std::string mime;
  bool gzipped = false;
};
using EncodeStep = std::function<EncodedFrame(std::size_t step)>;

// Writes steps first..last (0-based, inclusive) of `plan`, each encoded by `encode`, to `out`,
// atomically. Throws std::invalid_argument for an empty range, std::runtime_error naming the file
// (and the step) when a frame cannot be encoded or the file written.
HtmlPlayerResult write_step_page(const StepPlan& plan, Size frame, std::size_t first,
                                 std::size_t last, const EncodeStep& encode,
                                 const std::filesystem::path& out,
                                 const HtmlPlayerOptions& options, Progress* progress = nullptr);

// The same page with each step's display list as an SVG document (viz/svg_frame.hpp), gzipped.
HtmlPlayerResult write_svg_step_page(FrameSequence& sequence, std::size_t first, std::size_t last,
                                     const std::filesystem::path& out,
                                     const HtmlPlayerOptions& options,
                                     Progress* progress = nullptr);

// Standard base64 (RFC 4648, with padding), as data: URLs need it.
std::string base64(const std::vector<unsigned char>& bytes);

}  // namespace scantrace::viz
