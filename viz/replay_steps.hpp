#pragma once
// What a replay shows, as a list of steps; each step becomes one frame (held for a while in a
// video). Two plans:
//
//   triangles: title; then for every triangle its set-up (vertices and colours), the edge table
//              being built (one step per entry), its scanlines (one per step, or grouped), and the
//              finished triangle; end card. A skipped triangle gets one step saying why.
//   scene:     title; the painter's algorithm, triangles in drawing order (far to near) in
//              batches, so that 10,000 triangles make at most `max_scene_steps` steps; the
//              finished image; end card.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "trace/trace.hpp"

namespace scantrace::viz {

using i64 = std::int64_t;

enum class ReplayMode { automatic, triangles, scene };
ReplayMode parse_replay_mode(const std::string& text);  // throws std::invalid_argument
const char* to_string(ReplayMode mode);

struct StepOptions {
  // automatic: `triangles` when the trace holds at most one triangle, `scene` otherwise.
  ReplayMode mode = ReplayMode::automatic;
  // Scanlines per step; 0 chooses the smallest group size that keeps a triangle within
  // `max_scanline_steps` scanline steps. Rows where an edge enters or leaves the active edge
  // table always get a step of their own, so those moments are never hidden inside a group.
  int rows_per_step = 0;
  int max_scanline_steps = 40;
  int max_scene_steps = 100;  // painter's batches of a scene
};

enum class StepKind {
  title,
  triangle_setup,    // vertices, snapped vertices, colours
  edge_table_entry,  // the edge table with entries 0..entry listed, the last one just added
  scanlines,         // rows first_row..last_row filled; last_row is the current scanline
  triangle_done,
  triangle_skipped,
  painter_batch,  // scene: triangles order[first..last] drawn; order[last] is highlighted
  scene_done,
  end
};
const char* to_string(StepKind kind);

struct Step {
  StepKind kind = StepKind::title;
  int triangle = -1;  // the triangle explained (for painter batches: the highlighted one)
  int entry = 0;      // edge_table_entry: index into edges, then horizontal edges
  i64 first_row = 0, last_row = 0;
  int first_number = 0, last_number = 0;  // scanlines: 1-based positions among the traced rows
  int scanline_count = 0;                 // scanlines: rows this triangle has in the trace
  std::size_t first = 0, last = 0;        // painter_batch: positions in drawing order
  // How long the step is held, in multiples of the per-step hold time: text-heavy cards and the
  // moments an edge enters or leaves get longer.
  double weight = 1;
};

struct StepPlan {
  ReplayMode mode = ReplayMode::triangles;  // as resolved
  std::vector<int> order;                   // triangles in drawing order (as in the trace)
  std::vector<Step> steps;
  int rows_per_step = 1;  // the group size chosen for the last triangle planned (for messages)
};

StepPlan plan_steps(const trace::Trace& trace, const StepOptions& options = {});

// How many frames a step is held for: round(hold * fps * weight), at least one.
int frames_for(const Step& step, double fps, double hold_seconds);

}  // namespace scantrace::viz
