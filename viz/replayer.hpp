#pragma once
// A trace turned into frames, one per step, in order:
//
//   Replayer r(trace, {}, {1280, 720}, "triangle.jsonl");
//   for (std::size_t i = 0; i < r.steps().size(); ++i) use(r.frame(i));
//
// Each step adds the pixels it fills to the replay's canvas state as it is passed. Frames are
// cheapest in increasing step order (skipping ahead is fine: the skipped steps' pixels are still
// added); going back — the interactive player — restores the nearest earlier checkpoint of the
// canvas state and replays the steps from there.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "trace/trace.hpp"
#include "viz/canvas_state.hpp"
#include "viz/frame_composer.hpp"
#include "viz/replay_steps.hpp"

namespace scantrace::viz {

class Replayer {
 public:
  // `source` is how the title card names the input. Throws std::invalid_argument for a frame
  // size the layout cannot use, std::runtime_error when the canvas is too large to replay.
  Replayer(const trace::Trace& trace, const StepOptions& options, cv::Size frame,
           std::string source);

  const StepPlan& plan() const { return plan_; }
  const std::vector<Step>& steps() const { return plan_.steps; }
  cv::Size frame_size() const { return size_; }

  // The frame of step `index` (CV_8UC3, BGR, frame_size()), in any order; `placed`, when given,
  // receives where its markers, labels and zoom insets were drawn.
  cv::Mat frame(std::size_t index, std::vector<PlacedBox>* placed = nullptr);
  // Where canvas pixels appear on the frames of step `index` (nullopt on a card).
  std::optional<ViewGeometry> geometry(std::size_t index) const;
  const CanvasState& state() const { return state_; }
  // Ring `pixel` on every frame that shows the canvas (none: no ring).
  void mark_on_every_frame(std::optional<CanvasPixel> pixel) { marked_ = pixel; }

 private:
  void apply(const Step& step);
  void rewind(std::size_t index);
  static cv::Rect state_window(const trace::Trace& trace, const StepPlan& plan,
                               const FrameComposer& composer);

  const trace::Trace& trace_;
  StepPlan plan_;
  cv::Size size_;
  FrameComposer composer_;
  CanvasState state_;
  std::size_t applied_ = 0;  // steps whose pixels are in state_
  // Copies of state_ taken when `applied_` reached a multiple of checkpoint_every_ (key: applied_).
  std::map<std::size_t, CanvasState> checkpoints_;
  std::size_t checkpoint_every_ = 8;
  std::optional<CanvasPixel> marked_;
};

// The smallest frame the layout is designed for.
inline constexpr int kMinFrameWidth = 320, kMinFrameHeight = 180;

}  // namespace scantrace::viz
