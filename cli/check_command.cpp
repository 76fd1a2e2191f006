// scantrace check TRACE.jsonl [--partial]: verifies a trace thoroughly (trace/trace_check.hpp).
#include <memory>
#include <string>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/stopwatch.hpp"
#include "cli/trace_input.hpp"
#include "trace/trace_check.hpp"

namespace scantrace::cli {
namespace {

struct CheckArgs {
  std::string trace;
  bool partial = false;
};

void run(const CheckArgs& args) {
  Stopwatch load;
  // Loading parses every line and runs the cheap checks (as replay does).
  const trace::Trace t = load_trace(args.trace, args.partial);
  const double load_ms = load.ms();
  // Timed on their own, for the cost table of docs/robustness.md.
  Stopwatch cheap;
  trace::check_consistency(t.events(), args.trace, trace::CheckDepth::cheap);
  const double cheap_ms = cheap.ms();
  Stopwatch thorough;
  const trace::CheckSummary s =
      trace::check_consistency(t.events(), args.trace, trace::CheckDepth::thorough);
  const double thorough_ms = thorough.ms();
  spdlog::info(
      "{}: consistent: {} events, {} triangles, {} edge table entries, {} scanlines, {} pixel "
      "events; every edge table, crossing and span agrees with the exact values{}",
      args.trace, s.events, s.triangles, s.edges, s.scanlines, s.pixels,
      t.complete() ? "" : " (no footer: checked as far as the trace goes)");
  spdlog::info(
      "time: load with the cheap checks {:.0f} ms (the cheap checks alone {:.0f} ms), "
      "thorough checks {:.0f} ms",
      load_ms, cheap_ms, thorough_ms);
}

}  // namespace

Command add_check_command(CLI::App& app) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* cmd = app.add_subcommand(
      "check",
      "Verifies a trace (from 'scantrace trace') thoroughly: besides the checks every\n"
      "load makes (each event of a triangle that was begun and not yet ended, rows\n"
      "increasing and inside the edge table's rows, spans half-open on the canvas,\n"
      "active points sorted and finite, colours in [0, 1], entered/retired agreeing\n"
      "with the active set, the counts of triangle_end and the footer), it recomputes\n"
      "from the snapped vertices, in exact integer arithmetic, every edge table entry,\n"
      "every active edge's and active point's x (the exact crossing with the row) and\n"
      "every span (ceil(x_L) .. ceil(x_R) - 1, clipped). Exit status 0: consistent;\n"
      "1: the first contradiction, as 'FILE:LINE: what'.");
  cmd->add_option("TRACE", args->trace, "trace file (.jsonl, trace format v1)")->required();
  cmd->add_flag("--partial", args->partial,
                "check a trace that was cut short (no footer) as far as it\n"
                "goes instead of refusing it");
  cmd->footer(
      "Examples:\n"
      "  scantrace check triangle.jsonl\n"
      "  scantrace check cut.jsonl --partial");
  return {cmd, [args] { run(*args); }};
}

}  // namespace scantrace::cli
