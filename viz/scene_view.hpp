#pragma once
// Frames of the painter's algorithm (a scene-level replay): the whole canvas with the pixels
// drawn so far and the current batch outlined, and a panel with the drawing order by depth.
#include <optional>
#include <vector>

#include "viz/frame.hpp"

#include "trace/trace.hpp"
#include "viz/canvas_state.hpp"
#include "viz/replay_steps.hpp"
#include "viz/typography.hpp"
#include "viz/view_geometry.hpp"

namespace scantrace::viz {

// What every painter frame needs to know about the whole scene, gathered once.
struct SceneSummary {
  std::vector<std::optional<double>> depth;  // by position in drawing order
  std::optional<double> min_depth, max_depth;
  std::size_t skipped = 0;
  std::int64_t pixels = 0;  // from triangle_end events
};
SceneSummary summarize_scene(const trace::Trace& trace, const StepPlan& plan);

void draw_scene_view(FrameView& frame, const ViewGeometry& geometry, const Typography& type,
                     Size canvas, const CanvasState& state, const trace::Trace& trace,
                     const StepPlan& plan, const Step& step);

void draw_scene_panel(FrameView& frame, const Rect& area, const Typography& type,
                      const trace::Trace& trace, const StepPlan& plan, const SceneSummary& scene,
                      const Step& step, const CanvasState& state);

}  // namespace scantrace::viz
