#pragma once
// A trace turned into raster frames, one per step, in order: the display lists of FrameSequence
// (viz/frame_sequence.hpp) drawn by the OpenCV backend (viz/opencv/frame_raster.hpp).
//
//   Replayer r(trace, {}, {1280, 720}, "triangle.jsonl");
//   for (std::size_t i = 0; i < r.steps().size(); ++i) use(r.frame(i));
//
// Frames are cheapest in increasing step order; going back restores the nearest earlier
// checkpoint of the canvas state (FrameSequence).
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "trace/trace.hpp"
#include "viz/frame_sequence.hpp"

namespace scantrace::viz {

class Replayer {
 public:
  // `source` is how the title card names the input. Throws std::invalid_argument for a frame
  // size the layout cannot use, std::runtime_error when the canvas is too large to replay.
  Replayer(const trace::Trace& trace, const StepOptions& options, cv::Size frame,
           std::string source)
      : sequence_(trace, options, frame, std::move(source)) {}

  const StepPlan& plan() const { return sequence_.plan(); }
  const std::vector<Step>& steps() const { return sequence_.steps(); }
  cv::Size frame_size() const { return sequence_.frame_size(); }

  // The frame of step `index` (CV_8UC3, BGR, frame_size()), in any order; `placed`, when given,
  // receives where its markers, labels and zoom insets were drawn.
  cv::Mat frame(std::size_t index, std::vector<PlacedBox>* placed = nullptr);
  // The same frame as a display list.
  Frame display_list(std::size_t index, std::vector<PlacedBox>* placed = nullptr) {
    return sequence_.frame(index, placed);
  }
  // Where canvas pixels appear on the frames of step `index` (nullopt on a card).
  std::optional<ViewGeometry> geometry(std::size_t index) const {
    return sequence_.geometry(index);
  }
  const CanvasState& state() const { return sequence_.state(); }
  // Ring `pixel` on every frame that shows the canvas (none: no ring); FrameSequence says more.
  void mark_on_every_frame(std::optional<CanvasPixel> pixel) {
    sequence_.mark_on_every_frame(pixel);
  }

 private:
  FrameSequence sequence_;
};

}  // namespace scantrace::viz
