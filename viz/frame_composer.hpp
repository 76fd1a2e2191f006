#pragma once
// Puts a frame together for one step: title bar, the magnified canvas with its marks, the side
// panel and the legend — or a title or end card.
#include <optional>
#include <string>
#include <vector>

#include "viz/frame.hpp"

#include "trace/trace.hpp"
#include "viz/canvas_state.hpp"
#include "viz/cards.hpp"
#include "viz/frame_layout.hpp"
#include "viz/label_placement.hpp"
#include "viz/replay_steps.hpp"
#include "viz/scene_view.hpp"
#include "viz/typography.hpp"
#include "viz/view_geometry.hpp"

namespace scantrace::viz {

class FrameComposer {
 public:
  FrameComposer(const trace::Trace& trace, const StepPlan& plan, Size frame, std::string source);

  // The frame of `step` (number `index` in the plan) with the pixels of `state`. `placed`, when
  // given, receives where the markers, labels and zoom insets on the canvas view were drawn.
  Frame compose(const Step& step, std::size_t index, const CanvasState& state,
                std::vector<PlacedBox>* placed = nullptr) const;
  // Where the canvas is shown for `step` (nullopt: a card, no canvas).
  std::optional<ViewGeometry> geometry(const Step& step) const;
  // Makes every frame about one pixel (`why --explain`): it is ringed wherever the canvas shows,
  // the legend says what the ring is, and the views of the whole scene (painter's batches, the
  // cards) frame the traced faces and the pixel instead of the whole canvas, where a few faces
  // around a pixel of a 512² canvas would cover a few screen pixels. nullopt: no pixel.
  void mark(std::optional<CanvasPixel> pixel);
  const FrameLayout& layout() const { return layout_; }

 private:
  void title_bar(FrameView& frame, const Step& step, std::size_t index) const;
  void triangle_frame(FrameView& frame, const Step& step, const CanvasState& state,
                      std::vector<PlacedBox>* placed) const;
  void scene_frame(FrameView& frame, const Step& step, const CanvasState& state) const;
  void card_picture(FrameView& frame, const Step& step, const CanvasState& state,
                    std::vector<PlacedBox>* placed) const;

  const trace::Trace& trace_;
  const StepPlan& plan_;
  Size size_, canvas_;
  Typography type_;
  FrameLayout layout_;
  SceneSummary scene_;
  std::string source_;
  std::optional<CanvasPixel> marked_;
  PixelBox scene_region_;  // what the views of the whole scene frame: the canvas, or mark()'s
};

// The canvas pixels a view of `triangle` is centred on: its bounding box on the canvas, with a
// margin (the whole canvas when the triangle has no set-up in the trace).
PixelBox triangle_region(const trace::Trace& trace, int triangle);

}  // namespace scantrace::viz
