// scantrace explain (SCENE | --triangle "…" [--colors "…"] [--size WxH]) [trace filters]
//                   [fill options] -o OUT.mp4|OUT_DIR/ [replay options]
// `trace` and `replay` in one go: the trace stays in memory.
#include <memory>
#include <string>
#include <variant>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/fill_flags.hpp"
#include "cli/model_flags.hpp"
#include "cli/record_in_memory.hpp"
#include "cli/replay_flags.hpp"
#include "cli/trace_flags.hpp"
#include "io/obj_loader.hpp"
#include "trace/record.hpp"

namespace scantrace::cli {
namespace {

struct ExplainArgs {
  TraceFlags what;
  FillFlags fill;
  ModelFlags model;
  ReplayFlags replay;
};

void run(const ExplainArgs& args) {
  const trace::Trace t = record_in_memory(args.what, args.fill, args.model);
  if (t.truncated())
    spdlog::warn(
        "warning: the trace was truncated after {} events (--max-events, default 2000000 "
        "for explain); the video shows the steps before the cut",
        t.footer()->events);
  run_replay(t, args.replay, args.what.input_name());
}

}  // namespace

Command add_explain_command(CLI::App& app) {
  auto args = std::make_shared<ExplainArgs>();
  CLI::App* cmd = app.add_subcommand(
      "explain",
      "Traces a scene or one triangle and replays the trace into an explanatory\n"
      "video (or PNG frames) in one go: 'scantrace trace' and 'scantrace replay'\n"
      "without the file in between. Takes the inputs of 'trace' and the outputs of\n"
      "'replay'; --size is the canvas (as in render and trace), --video-size the\n"
      "frame size of the video.");
  add_trace_flags(*cmd, args->what);
  add_fill_flags(*cmd, args->fill);
  add_model_flags(*cmd, args->model, true);
  add_replay_flags(*cmd, args->replay, false);
  cmd->callback([args] { args->what.check(args->fill.fill_rule, args->fill.method); });
  cmd->footer(
      "Examples:\n"
      "  scantrace explain --triangle \"20,20 250,80 300,400\" -o triangle.mp4\n"
      "  scantrace explain --triangle \"2,1 9,3 4,8\" --size 12x10 -o small.mp4\n"
      "  scantrace explain --polygon \"10,1 13,19 1,7 19,7 7,19\" --winding non-zero\n"
      "                    --size 20x20 -o star.mp4\n"
      "  scantrace explain scene.json -o painter.mp4\n"
      "  scantrace explain scene.json --triangles 17 -o face17.mp4 --video-size 1920x1080");
  return {cmd, [args] { run(*args); }};
}

}  // namespace scantrace::cli
