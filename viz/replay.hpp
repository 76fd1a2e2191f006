#pragma once
// Replaying a trace into an explanatory video or a directory of frames, in one call:
//
//   const trace::Trace t = trace::Trace::load("triangle.jsonl");
//   viz::replay(t, "triangle.mp4");                 // H.264, 1280x720, 5 fps
//   viz::replay(t, "frames/", {.size = {1920, 1080}});
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "trace/trace.hpp"
#include "viz/progress.hpp"
#include "viz/replay_steps.hpp"
#include "viz/time_budget.hpp"
#include "viz/view_geometry.hpp"

namespace scantrace::viz {

// Steps first..last, 1-based and inclusive, written "A:B"; either side may be omitted ("5:",
// ":20"), and "A" alone is the single step A.
struct StepRange {
  std::size_t first = 1, last = SIZE_MAX;
  static StepRange parse(const std::string& text);  // throws std::invalid_argument
};

inline constexpr std::size_t kDefaultMaxFrames = 20000;

struct ReplayOptions {
  cv::Size size{1280, 720};  // even, at least 320x180
  double fps = 5;            // video only: the frames are stills, so few are needed
  double hold = 0.8;  // seconds a plain step is held (cards and key steps longer); video only
  StepRange steps{};
  StepOptions plan{};
  std::string source{};  // how the title card names the input (default: "the trace")
  // The most frames a replay may write (video frames, or PNG files): checked before the first
  // frame is drawn, so a trace too long to replay is a clear error, not hours of encoding or a
  // full disk. 20,000 frames is over an hour of video at 5 fps.
  std::size_t max_frames = kDefaultMaxFrames;
  // The longest a replay may take to draw, in seconds, checked as it goes (viz/time_budget.hpp).
  double max_seconds = kDefaultMaxMinutes * 60;
  // A pixel ringed on every frame that shows the canvas (`why --explain`: the pixel asked about).
  std::optional<CanvasPixel> marked_pixel{};
  // A frame directory's files: "png" (OpenCV's raster) or "svg" (viz/svg_frame.hpp).
  std::string frame_format = "png";
};

// Throws std::invalid_argument naming the option that is out of range.
void validate(const ReplayOptions& options);

enum class OutputKind { video, frames, html, svg };
// ".mp4" is a video; ".html" (".htm") a self-contained interactive page (viz/html_player.hpp);
// ".svg" the SVG of one step (the range must hold exactly one); a path ending in '/', an existing
// directory or a name without extension is a frame directory; anything else throws
// std::invalid_argument.
OutputKind output_kind(const std::filesystem::path& out);

struct ReplayResult {
  OutputKind kind = OutputKind::video;
  std::string format;           // "h264", "mpeg4", "png", "svg" or (html) the frames' "webp"
  std::size_t steps_total = 0;  // steps in the plan
  std::size_t steps = 0;        // rendered (the selected range)
  std::size_t frames = 0;       // written (video: steps times their hold; frames: = steps)
  double seconds = 0;           // video duration
  std::size_t bytes = 0;        // html: the page's size
  ReplayMode mode = ReplayMode::triangles;
  int rows_per_step = 1;
};

ReplayResult replay(const trace::Trace& trace, const std::filesystem::path& out,
                    const ReplayOptions& options = {}, Progress* progress = nullptr);

}  // namespace scantrace::viz
