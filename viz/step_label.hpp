#pragma once
// One line naming a replay step, for lists of steps (the HTML player's index, the window's
// title): "scanline y = 80 (61 of 380)", "edge table: entry 2", "painter: drawn 1-100 of 437
// (highlighted: triangle 12)" (positions in the drawing order, then a face).
#include <cstddef>
#include <string>

#include "viz/replay_steps.hpp"

namespace scantrace::viz {

std::string step_label(const StepPlan& plan, const Step& step);

// The step of `plan` whose scanlines include canvas row `row` (the first such step), or the
// number of steps when no step shows that row: what "go to row" jumps to.
std::size_t step_of_row(const StepPlan& plan, i64 row);

}  // namespace scantrace::viz
