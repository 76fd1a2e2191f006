#include "viz/replay_steps.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>

namespace scantrace::viz {
namespace {

// Hold weights (multiples of the per-step hold time). Cards and set-up carry paragraphs of text;
// a scanline step is one glance; the rows where the active edge table changes deserve two.
constexpr double kCardWeight = 3;
constexpr double kSetupWeight = 3;
constexpr double kEntryWeight = 2;
constexpr double kEventRowWeight = 2;
constexpr double kDoneWeight = 3;
constexpr double kSkippedWeight = 2;
// The painting phase of a scene lasts about this many holds in all, however many batches it has
// (each batch held between a quarter and a whole hold).
constexpr double kPainterHolds = 25;

bool changes_active_edges(const trace::Scanline& s) {
  return !s.entered.empty() || !s.retired.empty();
}

void plan_scanlines(const trace::Trace& trace, int triangle, const StepOptions& options,
                    StepPlan& plan) {
  const std::vector<const trace::Scanline*> rows = trace.scanlines(triangle);
  if (rows.empty()) return;
  const std::size_t n = rows.size();
  const std::size_t group =
      options.rows_per_step > 0
          ? static_cast<std::size_t>(options.rows_per_step)
          : std::max<std::size_t>(
                1, (n + std::max(1, options.max_scanline_steps) - 1) /
                       static_cast<std::size_t>(std::max(1, options.max_scanline_steps)));
  plan.rows_per_step = static_cast<int>(group);
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    if (!changes_active_edges(*rows[i]))
      while (j + 1 < n && j + 1 - i < group && !changes_active_edges(*rows[j + 1]) &&
             rows[j + 1]->y == rows[j]->y + 1)
        ++j;
    Step s;
    s.kind = StepKind::scanlines;
    s.triangle = triangle;
    s.first_row = rows[i]->y;
    s.last_row = rows[j]->y;
    s.first_number = static_cast<int>(i + 1);
    s.last_number = static_cast<int>(j + 1);
    s.scanline_count = static_cast<int>(n);
    s.weight = changes_active_edges(*rows[i]) ? kEventRowWeight : 1;
    plan.steps.push_back(s);
    i = j + 1;
  }
}

void plan_triangle(const trace::Trace& trace, int triangle, const StepOptions& options,
                   StepPlan& plan) {
  if (trace.skipped(triangle)) {
    plan.steps.push_back(
        {.kind = StepKind::triangle_skipped, .triangle = triangle, .weight = kSkippedWeight});
    return;
  }
  // A filtered or cut trace may hold later events of a triangle only.
  const bool begun = trace.find_triangle_begin(triangle) != nullptr;
  if (begun)
    plan.steps.push_back(
        {.kind = StepKind::triangle_setup, .triangle = triangle, .weight = kSetupWeight});
  if (const trace::EdgeTableEvent* table = trace.find_edge_table(triangle)) {
    const int entries = static_cast<int>(table->edges.size() + table->horizontal.size());
    for (int e = 0; e < entries; ++e)
      plan.steps.push_back({.kind = StepKind::edge_table_entry,
                            .triangle = triangle,
                            .entry = e,
                            .weight = kEntryWeight});
  }
  plan_scanlines(trace, triangle, options, plan);
  if (begun)
    plan.steps.push_back(
        {.kind = StepKind::triangle_done, .triangle = triangle, .weight = kDoneWeight});
}

void plan_scene(const trace::Trace& trace, const StepOptions& options, StepPlan& plan) {
  const std::size_t n = plan.order.size();
  if (n == 0) return;
  const std::size_t max_steps = static_cast<std::size_t>(std::max(1, options.max_scene_steps));
  const std::size_t batch = (n + max_steps - 1) / max_steps;
  const std::size_t batches = (n + batch - 1) / batch;
  const double weight = std::clamp(kPainterHolds / static_cast<double>(batches), 0.25, 1.0);
  for (std::size_t first = 0; first < n; first += batch) {
    Step s;
    s.kind = StepKind::painter_batch;
    s.first = first;
    s.last = std::min(n, first + batch) - 1;
    s.weight = weight;
    // Highlight the last triangle of the batch that drew something.
    for (std::size_t i = s.last + 1; i-- > s.first;)
      if (!trace.skipped(plan.order[i])) {
        s.triangle = plan.order[i];
        break;
      }
    plan.steps.push_back(s);
  }
  plan.steps.push_back({.kind = StepKind::scene_done, .weight = kDoneWeight});
}

}  // namespace

ReplayMode parse_replay_mode(const std::string& text) {
  if (text == "auto") return ReplayMode::automatic;
  if (text == "triangles") return ReplayMode::triangles;
  if (text == "scene") return ReplayMode::scene;
  throw std::invalid_argument(
      fmt::format("replay mode \"{}\" is not auto, triangles or scene", text));
}

const char* to_string(ReplayMode mode) {
  switch (mode) {
    case ReplayMode::automatic:
      return "auto";
    case ReplayMode::triangles:
      return "triangles";
    case ReplayMode::scene:
      return "scene";
  }
  return "?";
}

const char* to_string(StepKind kind) {
  switch (kind) {
    case StepKind::title:
      return "title";
    case StepKind::triangle_setup:
      return "triangle set-up";
    case StepKind::edge_table_entry:
      return "edge table";
    case StepKind::scanlines:
      return "scanlines";
    case StepKind::triangle_done:
      return "triangle done";
    case StepKind::triangle_skipped:
      return "triangle skipped";
    case StepKind::painter_batch:
      return "painter's batch";
    case StepKind::scene_done:
      return "scene done";
    case StepKind::end:
      return "end";
  }
  return "?";
}

StepPlan plan_steps(const trace::Trace& trace, const StepOptions& options) {
  StepPlan plan;
  for (int t : trace.triangles())
    if (t >= 0) plan.order.push_back(t);
  plan.mode = options.mode != ReplayMode::automatic ? options.mode
              : plan.order.size() <= 1              ? ReplayMode::triangles
                                                    : ReplayMode::scene;
  plan.steps.push_back({.kind = StepKind::title, .weight = kCardWeight});
  if (plan.mode == ReplayMode::scene)
    plan_scene(trace, options, plan);
  else
    for (int t : plan.order) plan_triangle(trace, t, options, plan);
  plan.steps.push_back({.kind = StepKind::end, .weight = kCardWeight});
  return plan;
}

int frames_for(const Step& step, double fps, double hold_seconds) {
  return std::max(1, static_cast<int>(std::lround(hold_seconds * fps * step.weight)));
}

}  // namespace scantrace::viz
