#pragma once
// The title and end cards: what the video shows, and a recap once it has shown it.
#include <string>
#include <vector>

#include "viz/frame.hpp"

#include "trace/trace.hpp"
#include "viz/replay_steps.hpp"
#include "viz/typography.hpp"

namespace scantrace::viz {

struct CardInfo {
  std::string source;       // the trace's name, or what was traced (for explain)
  int rows_per_step = 1;    // scanline grouping, mentioned when > 1
  std::int64_t pixels = 0;  // written in all (end card)
  std::int64_t overwrites = 0;
  std::int64_t rejected = 0;  // z-buffer: pixels the depth test rejected
};

// The visibility rule the trace's render used, as the cards and frames name it:
// "z-buffer (a depth test per pixel)" or "painter's algorithm (far to near)".
std::string visibility_rule(const trace::Header& header);
bool uses_zbuffer(const trace::Header& header);

// The lines of the end card's recap (what the video has shown), for the trace's visibility rule.
std::vector<std::string> recap_lines(const trace::Trace& trace, const StepPlan& plan);

// Where a card shows its picture (the triangle or the scene), right of its text.
Rect card_picture_area(Size frame, const Typography& type);

void draw_title_card(FrameView& frame, const Typography& type, const trace::Trace& trace,
                     const StepPlan& plan, const CardInfo& info);
void draw_end_card(FrameView& frame, const Typography& type, const trace::Trace& trace,
                   const StepPlan& plan, const CardInfo& info);

}  // namespace scantrace::viz
