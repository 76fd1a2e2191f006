#pragma once
// What the interactive player (`scantrace step`) draws over or below a replay frame: the pixel a
// click selected, marked on the magnified canvas, with its history so far in a box over the side
// panel; the status strip with the step counter and the key hint; the key help.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "viz/frame.hpp"

#include "trace/trace.hpp"
#include "viz/replay_steps.hpp"
#include "viz/typography.hpp"
#include "viz/view_geometry.hpp"

namespace scantrace::viz {

// The canvas pixel shown at frame point `p`, when `p` lies on the magnified canvas `g` and the
// pixel on the canvas (`canvas` pixels wide and high).
std::optional<CanvasPixel> pixel_at(const ViewGeometry& g, Point p, Size canvas);

// A ring around the pixel's cell (at least a few frame pixels wide, so a pixel is visible even
// when cells are one frame pixel), clipped to the view.
void mark_pixel(FrameView& frame, const ViewGeometry& g, CanvasPixel pixel);

// The history of `pixel` up to and including step `index` of `plan`, from the trace: every write
// in drawing order — which triangle (face), the row and span that wrote it, with which colour.
std::vector<std::string> pixel_history_lines(const trace::Trace& trace, const StepPlan& plan,
                                             std::size_t index, CanvasPixel pixel);

// `lines` on a boxed panel at the bottom of `area` (the side panel), over what is there.
void draw_history_box(FrameView& frame, const Rect& area, const Typography& type,
                      const std::vector<std::string>& lines);

// `lines` (the player's keys, from the players' key table web/player/keys.json), boxed in the
// middle of the frame.
void draw_key_help(FrameView& frame, const Typography& type, const std::vector<std::string>& lines);

// A strip `height` high: `left` (the step counter, a prompt) and `right` (the key hint).
Frame compose_status_strip(int width, int height, const Typography& type, const std::string& left,
                           const std::string& right);

}  // namespace scantrace::viz
