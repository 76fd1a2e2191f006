// scantrace trace (SCENE | --triangle "…" | --polygon "…" [--winding …]) [--colors "…"] [filters]
//                 -o OUT.jsonl
#include <filesystem>
#include <memory>
#include <string>
#include <variant>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/fill_flags.hpp"
#include "cli/model_flags.hpp"
#include "cli/selection_check.hpp"
#include "cli/stopwatch.hpp"
#include "cli/trace_flags.hpp"
#include "io/obj_loader.hpp"
#include "trace/record.hpp"

namespace scantrace::cli {
namespace {

struct TraceArgs {
  TraceFlags what;
  FillFlags fill;
  ModelFlags model;
  std::string output;
  // A full disk is not how a pixel-level trace of a large scene should end.
  long long max_bytes = 1LL << 30;
};

void run_trace(const TraceArgs& args) {
  FillOptions options = args.model.apply(args.fill.options(), is_obj_file(args.what.scene));
  options.winding_rule = args.what.winding_rule();
  const auto input = trace_input(args.what, args.model, options.shading, args.fill.clamp_colors);
  trace::TraceFilter filter = args.what.filter();
  check_selection(input, filter, args.what.input_name());
  filter.max_bytes = args.max_bytes;
  const Stopwatch clock;
  const trace::Footer footer = std::visit(
      [&](const auto& in) {
        if constexpr (std::is_same_v<std::decay_t<decltype(in)>, Scene>)
          return trace::write_scene_trace(args.output, in, options, filter);
        else if constexpr (std::is_same_v<std::decay_t<decltype(in)>, trace::GeneralPolygonInput>)
          return trace::write_polygon_trace(args.output, in, options, filter);
        else
          return trace::write_triangle_trace(args.output, in, options, filter);
      },
      input);
  spdlog::info("traced {} ({} level, {} shading): {} events in {:.1f} ms -> {}",
               args.what.input_name(), args.what.level, to_string(options.shading), footer.events,
               clock.ms(), args.output);
  if (footer.truncated) {
    // Name the budget that cut it: the event count reached --max-events, or else the bytes.
    const bool by_events = filter.max_events && footer.events >= *filter.max_events;
    const std::string budget = by_events ? "--max-events " + std::to_string(*filter.max_events)
                                         : "--max-bytes " + std::to_string(args.max_bytes);
    spdlog::warn(
        "warning: {}: the trace was truncated after {} events by its budget {}; its footer says "
        "\"truncated\": true",
        args.output, footer.events, budget);
  }
}

}  // namespace

Command add_trace_command(CLI::App& app) {
  auto args = std::make_shared<TraceArgs>();
  CLI::App* cmd = app.add_subcommand(
      "trace",
      "Fills a scene, one triangle or one general polygon and writes what the\n"
      "edge-table fill did, step by step, as JSON Lines (trace format v1): each\n"
      "triangle's setup and edge table, then per scanline the edges that entered\n"
      "and retired, the active edges and their exact x, the active points with\n"
      "their colours, and the span filled (for a polygon: every inside interval,\n"
      "and each active edge's winding direction).");
  add_trace_flags(*cmd, args->what);
  add_fill_flags(*cmd, args->fill);
  add_model_flags(*cmd, args->model, true);
  cmd->add_option("-o,--output", args->output, "output trace (.jsonl)")->required();
  cmd->add_option("--max-bytes", args->max_bytes,
                  "stop before the file would exceed N bytes; the footer\nthen says truncated")
      ->check(CLI::Range(1024LL, 1LL << 50))
      ->capture_default_str();
  cmd->callback([args] { args->what.check(args->fill.fill_rule, args->fill.method); });
  cmd->footer(
      "Examples:\n"
      "  scantrace trace --triangle \"20,20 250,80 300,400\" -o triangle.jsonl\n"
      "  scantrace trace --polygon \"2,2 30,2 30,30 2,30 | 10,10 22,10 22,22 10,22\"\n"
      "                  --winding non-zero --size 32x32 -o hole.jsonl\n"
      "  scantrace trace scene.json --triangles 3,17,40-45 --rows 100:120 -o part.jsonl\n"
      "  scantrace trace scene.json --level pixel --max-events 100000 -o pixels.jsonl");
  return {cmd, [args] { run_trace(*args); }};
}

}  // namespace scantrace::cli
