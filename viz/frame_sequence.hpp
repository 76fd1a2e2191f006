#pragma once
// A trace turned into display lists, one per step, in order (the composer's half of the replay;
// viz/replayer.hpp draws them with OpenCV, viz/svg_frame.hpp as SVG):
//
//   FrameSequence s(trace, {}, {1280, 720}, "triangle.jsonl");
//   for (std::size_t i = 0; i < s.steps().size(); ++i) use(s.frame(i));
//
// Each step adds the pixels it fills to the replay's canvas state as it is passed. Frames are
// cheapest in increasing step order (skipping ahead is fine: the skipped steps' pixels are still
// added); going back — the interactive player — restores the nearest earlier checkpoint of the
// canvas state (taken from the first time it goes back on) and replays the steps from there.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "trace/trace.hpp"
#include "viz/canvas_state.hpp"
#include "viz/frame.hpp"
#include "viz/frame_composer.hpp"
#include "viz/replay_steps.hpp"

namespace scantrace::viz {

// The smallest frame the layout is designed for.
inline constexpr int kMinFrameWidth = 320, kMinFrameHeight = 180;

class FrameSequence {
 public:
  // `source` is how the title card names the input. Throws std::invalid_argument for a frame
  // size the layout cannot use, std::runtime_error when the canvas is too large to replay.
  FrameSequence(const trace::Trace& trace, const StepOptions& options, Size frame,
                std::string source);

  const StepPlan& plan() const { return plan_; }
  const std::vector<Step>& steps() const { return plan_.steps; }
  Size frame_size() const { return size_; }

  // The display list of step `index`, in any order; `placed`, when given, receives where its
  // markers, labels and zoom insets were placed.
  Frame frame(std::size_t index, std::vector<PlacedBox>* placed = nullptr);
  // Where canvas pixels appear on the frames of step `index` (nullopt on a card).
  std::optional<ViewGeometry> geometry(std::size_t index) const;
  const CanvasState& state() const { return state_; }
  // Ring `pixel` on every frame that shows the canvas (none: no ring); the frames are then about
  // it (FrameComposer::mark: the legend names the ring, the scene views frame the traced faces).
  void mark_on_every_frame(std::optional<CanvasPixel> pixel) {
    marked_ = pixel;
    composer_.mark(pixel);
  }

 private:
  void apply(const Step& step);
  void rewind(std::size_t index);
  static Rect state_window(const trace::Trace& trace, const StepPlan& plan,
                           const FrameComposer& composer);

  const trace::Trace& trace_;
  StepPlan plan_;
  Size size_;
  FrameComposer composer_;
  CanvasState state_;
  std::size_t applied_ = 0;  // steps whose pixels are in state_
  // Copies of state_ taken when `applied_` reached a multiple of checkpoint_every_ (key: applied_)
  // after the first rewind; the state of no step is made afresh, not kept.
  std::map<std::size_t, CanvasState> checkpoints_;
  bool rewound_ = false;
  std::size_t checkpoint_every_ = 8;
  std::optional<CanvasPixel> marked_;
};

}  // namespace scantrace::viz
