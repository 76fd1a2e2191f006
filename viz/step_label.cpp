#include "viz/step_label.hpp"

#include <spdlog/fmt/fmt.h>

namespace scantrace::viz {

std::string step_label(const StepPlan& plan, const Step& s) {
  switch (s.kind) {
    case StepKind::title:
      return "title";
    case StepKind::triangle_setup:
      return fmt::format("triangle {}: set-up", s.triangle);
    case StepKind::edge_table_entry:
      return fmt::format("triangle {}: edge table, entry {}", s.triangle, s.entry);
    case StepKind::scanlines:
      if (s.first_row == s.last_row)
        return fmt::format("scanline y = {} ({} of {})", s.last_row, s.last_number,
                           s.scanline_count);
      return fmt::format("scanlines y = {}..{} ({}-{} of {})", s.first_row, s.last_row,
                         s.first_number, s.last_number, s.scanline_count);
    case StepKind::triangle_done:
      return fmt::format("triangle {}: done", s.triangle);
    case StepKind::triangle_skipped:
      return fmt::format("triangle {}: skipped", s.triangle);
    case StepKind::painter_batch:
      // Positions in the drawing order, not face numbers (those are the trace's "triangle"
      // indices): the highlighted face is named as such.
      return fmt::format("painter: drawn {}-{} of {} (highlighted: triangle {})", s.first + 1,
                         s.last + 1, plan.order.size(), s.triangle);
    case StepKind::scene_done:
      return "the finished image";
    case StepKind::end:
      return "end";
  }
  return "step";
}

std::size_t step_of_row(const StepPlan& plan, i64 row) {
  for (std::size_t i = 0; i < plan.steps.size(); ++i) {
    const Step& s = plan.steps[i];
    if (s.kind == StepKind::scanlines && s.first_row <= row && row <= s.last_row) return i;
  }
  return plan.steps.size();
}

}  // namespace scantrace::viz
