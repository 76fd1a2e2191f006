#pragma once
// The options of a replay, shared by `replay` and `explain` so they are spelled and explained the
// same in both:
//   -o OUT.mp4|OUT_DIR/|OUT.html|OUT.svg [--fps N] [--hold SECONDS] [--video-size WxH] [--steps
//   A:B]
//   [--rows-per-step N] [--mode auto|triangles|scene] [--format png|svg]
// --size means the canvas everywhere (cli/canvas_size.hpp); `replay`, which has no canvas,
// still accepts its old --size for the frame as a deprecated alias (`size_is_free`).
#include <string>

#include "viz/replay.hpp"

namespace CLI {
class App;
}

namespace scantrace::cli {

struct ReplayFlags {
  std::string output;
  double fps = 5;
  double hold = 0.8;
  std::string size = "1280x720";
  std::string steps;
  int rows_per_step = 0;
  std::string mode = "auto";
  std::size_t max_frames = viz::kDefaultMaxFrames;
  double max_minutes = viz::kDefaultMaxMinutes;
  std::string format = "png";                      // a frame directory's files: png or svg
  bool frames_page = false;  // OUT.html: pre-drawn frames, not the trace and its player (cli/trace_page.hpp)
  std::optional<viz::CanvasPixel> marked_pixel{};  // not an option: set by `why --explain`

  viz::ReplayOptions options(const std::string& source) const;
};

void add_replay_flags(CLI::App& command, ReplayFlags& flags, bool size_is_free);

// "1280x720" -> frame size; throws std::invalid_argument unless both are even and in range.
cv::Size parse_video_size(const std::string& text);

// Replays `trace` as `flags` say, with a progress bar unless --quiet, and logs one line with
// what was written.
void run_replay(const trace::Trace& trace, const ReplayFlags& flags, const std::string& source);

}  // namespace scantrace::cli
