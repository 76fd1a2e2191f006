#pragma once
// The right half of a triangle frame (docs/design.md §6): what the fill knows at this step — the
// vertices, the edge table, the active edge table, the active points and their colours, the span,
// and the formula being applied.
#include "viz/frame.hpp"

#include "trace/trace.hpp"
#include "viz/replay_steps.hpp"
#include "viz/typography.hpp"

namespace scantrace::viz {

// Writes the panel for `step` (a triangle step) into `area`; returns the height it used.
int draw_triangle_panel(FrameView& frame, const Rect& area, const Typography& type,
                        const trace::Trace& trace, const Step& step);

// Why the fill gave up on a triangle, in a sentence (from a triangle_skipped reason).
std::string explain_skip(const std::string& reason);

}  // namespace scantrace::viz
