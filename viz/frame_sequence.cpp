#include "viz/frame_sequence.hpp"

#include <algorithm>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>

#include "viz/step_overlay.hpp"

namespace scantrace::viz {
namespace {

// The replay keeps the written pixels of this many canvas pixels at most (3 bytes + mask each).
constexpr std::int64_t kMaxStatePixels = std::int64_t{1} << 26;

Size checked(Size frame) {
  if (frame.width < kMinFrameWidth || frame.height < kMinFrameHeight)
    throw std::invalid_argument(fmt::format("frame size {}x{} is too small (at least {}x{})",
                                            frame.width, frame.height, kMinFrameWidth,
                                            kMinFrameHeight));
  return frame;
}

}  // namespace

Rect FrameSequence::state_window(const trace::Trace& trace, const StepPlan& plan,
                                 const FrameComposer& composer) {
  const trace::CanvasSize c = trace.header().canvas;
  // Every pixel any frame shows; outside the canvas nothing is ever written.
  std::int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
  for (const Step& s : plan.steps)
    if (const auto g = composer.geometry(s)) {
      const PixelBox v = g->visible();
      x0 = std::min(x0, v.x0), y0 = std::min(y0, v.y0);
      x1 = std::max(x1, v.x1), y1 = std::max(y1, v.y1);
    }
  x0 = std::max<std::int64_t>(x0, 0), y0 = std::max<std::int64_t>(y0, 0);
  x1 = std::min<std::int64_t>(x1, c.width - 1), y1 = std::min<std::int64_t>(y1, c.height - 1);
  if (x1 < x0 || y1 < y0) return {0, 0, 0, 0};
  if ((x1 - x0 + 1) * (y1 - y0 + 1) > kMaxStatePixels)
    throw std::runtime_error(fmt::format(
        "the canvas ({}x{}) is too large to replay; trace fewer triangles", c.width, c.height));
  return {static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1 - x0 + 1),
          static_cast<int>(y1 - y0 + 1)};
}

FrameSequence::FrameSequence(const trace::Trace& trace, const StepOptions& options, Size frame,
                             std::string source)
    : trace_(trace),
      plan_(plan_steps(trace, options)),
      size_(checked(frame)),
      composer_(trace, plan_, size_, std::move(source)),
      state_(state_window(trace, plan_, composer_), trace) {
  // Checkpoints cost a copy of the state each (4 bytes a pixel): their spacing keeps them under
  // ~256 MB in all, and a step back then replays at most checkpoint_every_ steps.
  const std::size_t bytes = static_cast<std::size_t>(state_.window().area()) * 4 + 1;
  const std::size_t affordable = std::max<std::size_t>(1, (std::size_t{256} << 20) / bytes);
  checkpoint_every_ = std::max<std::size_t>(8, plan_.steps.size() / affordable + 1);
}

std::optional<ViewGeometry> FrameSequence::geometry(std::size_t index) const {
  return composer_.geometry(plan_.steps.at(index));
}

void FrameSequence::apply(const Step& step) {
  state_.forget_recent();  // the rejections a frame marks are those of its own step
  switch (step.kind) {
    case StepKind::triangle_done:
      // A triangle-level trace has no scanline steps: the finished triangle is its first
      // picture (filled again from the trace, CanvasState).
      if (trace_.header().level == TraceLevel::triangle)
        state_.paint_triangle(trace_, step.triangle);
      break;
    case StepKind::scanlines:
      state_.paint_rows(trace_, step.triangle, step.first_row, step.last_row);
      break;
    case StepKind::painter_batch:
      for (std::size_t i = step.first; i <= step.last && i < plan_.order.size(); ++i)
        state_.paint_triangle(trace_, plan_.order[i]);
      break;
    default:
      break;
  }
}

void FrameSequence::rewind(std::size_t index) {
  rewound_ = true;
  // The latest checkpoint at or before the state of step `index`; before the first one, the
  // state of no step (an empty canvas state of the same window).
  auto it = checkpoints_.upper_bound(index);
  if (it == checkpoints_.begin()) {
    state_ = CanvasState(state_.window(), trace_);
    applied_ = 0;
    return;
  }
  --it;
  state_ = it->second.clone();
  applied_ = it->first;
}

Frame FrameSequence::frame(std::size_t index, std::vector<PlacedBox>* placed) {
  if (index >= plan_.steps.size())
    throw std::out_of_range(
        fmt::format("step {} is beyond the replay's {} steps", index + 1, plan_.steps.size()));
  if (index + 1 < applied_) rewind(index);
  for (; applied_ <= index; ++applied_) {
    // Checkpoints only once the sequence has gone back (the interactive player): a sequence
    // asked for its frames in order, or for one frame (the explorer's mouse move, which builds a
    // sequence for one step), never restores one, and each is a copy of the whole canvas state.
    if (rewound_ && applied_ % checkpoint_every_ == 0 && applied_ > 0 &&
        !checkpoints_.count(applied_))
      checkpoints_.emplace(applied_, state_.clone());
    apply(plan_.steps[applied_]);
  }
  Frame f = composer_.compose(plan_.steps[index], index, state_, placed);
  if (marked_)
    if (const auto g = geometry(index)) {
      FrameView view(f);
      mark_pixel(view, *g, *marked_);
    }
  return f;
}

}  // namespace scantrace::viz
