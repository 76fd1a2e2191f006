#include "cli/trace_input.hpp"


#include <spdlog/spdlog.h>

#include "io/input_file.hpp"

namespace scantrace::cli {

// By default an incomplete trace is an error — a video of half a fill that looks complete would
// mislead; with --partial the complete lines are used and a warning says so.
trace::Trace load_trace(const std::string& file, bool partial) {
  // The reader says only that it cannot open the file; the system says why (or that it is a
  // FIFO or a device, which the reader does not open: io/input_file.hpp).
  if (const std::string problem = regular_file_problem(file); !problem.empty())
    throw trace::TraceError(file + ": cannot open trace: " + problem);
  if (!partial) {
    trace::Trace t = trace::Trace::load(file);
    if (!t.complete())
      throw trace::TraceError(file +
                              ": the trace has no footer, so it is incomplete (an interrupted "
                              "writer or a truncated file): " +
                              t.progress() + "; --partial replays them");
    return t;
  }
  // The complete lines are used: an unfinished last line (a writer cut off) is dropped.
  trace::Trace t = trace::Trace::load(file, true);
  if (t.dropped_last_line()) spdlog::warn("warning: {}: dropped an unfinished last line", file);
  if (!t.complete())
    spdlog::warn("warning: {}: the trace has no footer (cut short): {}; using the events it holds",
                 file, t.progress());
  return t;
}

void warn_if_truncated(const trace::Trace& t, const std::string& file) {
  if (!t.truncated()) return;
  spdlog::warn(
      "warning: {}: the trace was truncated after {} events by a budget of 'scantrace trace' "
      "(--max-events or --max-bytes); using the events it holds",
      file, t.footer()->events);
}

}  // namespace scantrace::cli
