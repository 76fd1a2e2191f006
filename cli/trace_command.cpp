// scantrace trace (SCENE | --triangle "…" [--colors "…"]) [filters] -o OUT.jsonl
#include <filesystem>
#include <memory>
#include <string>
#include <variant>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/fill_flags.hpp"
#include "cli/stopwatch.hpp"
#include "cli/trace_flags.hpp"
#include "trace/record.hpp"

namespace scantrace::cli {
namespace {

struct TraceArgs {
  TraceFlags what;
  FillFlags fill;
  std::string output;
  // A full disk is not how a pixel-level trace of a large scene should end.
  long long max_bytes = 1LL << 30;
};

void run_trace(const TraceArgs& args) {
  const auto input = args.what.input(args.fill.clamp_colors);
  trace::TraceFilter filter = args.what.filter();
  filter.max_bytes = args.max_bytes;
  const FillOptions options = args.fill.options();
  const Stopwatch clock;
  const trace::Footer footer = std::visit(
      [&](const auto& in) {
        if constexpr (std::is_same_v<std::decay_t<decltype(in)>, Scene>)
          return trace::write_scene_trace(args.output, in, options, filter);
        else
          return trace::write_triangle_trace(args.output, in, options, filter);
      },
      input);
  spdlog::info("traced {} ({} level, {} shading): {} events in {:.1f} ms -> {}",
               args.what.input_name(), args.what.level, to_string(options.shading), footer.events,
               clock.ms(), args.output);
  if (footer.truncated)
    spdlog::warn(
        "warning: {}: the trace was truncated after {} events (budget --max-events or "
        "--max-bytes {}); its footer says \"truncated\": true",
        args.output, footer.events, args.max_bytes);
}

}  // namespace

Command add_trace_command(CLI::App& app) {
  auto args = std::make_shared<TraceArgs>();
  CLI::App* cmd = app.add_subcommand(
      "trace",
      "Fills a scene or one triangle and writes what the edge-table fill did, step by\n"
      "step, as JSON Lines (trace format v1): each triangle's setup and edge table,\n"
      "then per scanline the edges that entered and retired, the active edges and\n"
      "their exact x, the active points with their colours, and the span filled.");
  add_trace_flags(*cmd, args->what);
  add_fill_flags(*cmd, args->fill);
  cmd->add_option("-o,--output", args->output, "output trace (.jsonl)")->required();
  cmd->add_option("--max-bytes", args->max_bytes,
                  "stop before the file would exceed N bytes; the footer\nthen says truncated")
      ->check(CLI::Range(1024LL, 1LL << 50))
      ->capture_default_str();
  cmd->callback([args] {
    if (args->what.scene.empty() && args->what.triangle.empty())
      throw CLI::RequiredError("a SCENE file or --triangle");
  });
  cmd->footer(
      "Examples:\n"
      "  scantrace trace --triangle \"20,20 250,80 300,400\" -o triangle.jsonl\n"
      "  scantrace trace scene.json --triangles 3,17,40-45 --rows 100:120 -o part.jsonl\n"
      "  scantrace trace scene.json --level pixel --max-events 100000 -o pixels.jsonl");
  return {cmd, [args] { run_trace(*args); }};
}

}  // namespace scantrace::cli
