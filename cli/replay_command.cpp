// scantrace replay TRACE.jsonl -o OUT.mp4|OUT_DIR/ [replay options] [--partial]
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/replay_flags.hpp"
#include "cli/trace_input.hpp"
#include "trace/trace.hpp"

namespace scantrace::cli {
namespace {

struct ReplayArgs {
  std::string trace;
  bool partial = false;
  ReplayFlags replay;
};

void run(const ReplayArgs& args) {
  const trace::Trace t = load_trace(args.trace, args.partial);
  warn_if_truncated(t, args.trace);
  run_replay(t, args.replay, args.trace);
}

}  // namespace

Command add_replay_command(CLI::App& app) {
  auto args = std::make_shared<ReplayArgs>();
  CLI::App* cmd = app.add_subcommand(
      "replay",
      "Turns a trace (from 'scantrace trace') into an explanatory video or PNG frames:\n"
      "for one triangle its set-up, the edge table being built, every scanline with\n"
      "its active edges, active points, span and colours, and the result; for a scene\n"
      "the triangles drawn under the render's visibility rule: the painter's algorithm\n"
      "(far to near) or the z-buffer (a depth test per pixel).");
  // A missing trace is bad input (exit status 1, "cannot open trace"), as a missing scene is for
  // render, not a usage error.
  cmd->add_option("TRACE", args->trace, "trace file (.jsonl, trace format v1)")->required();
  add_replay_flags(*cmd, args->replay, true);
  cmd->add_flag("--partial", args->partial,
                "replay a trace that was cut short (no footer) instead of\n"
                "refusing it");
  cmd->footer(
      "Examples:\n"
      "  scantrace replay triangle.jsonl -o triangle.mp4\n"
      "  scantrace replay triangle.jsonl -o frames/ --steps 5:12 --video-size 1920x1080\n"
      "  scantrace replay scene.jsonl -o painter.mp4 --hold 0.5");
  return {cmd, [args] { run(*args); }};
}

}  // namespace scantrace::cli
