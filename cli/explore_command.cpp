// scantrace explore [-o explorer.html]
// Writes the explorer (docs/web.md): one self-contained HTML page with the WebAssembly build of
// the fill, trace, frame composer, why and diff inlined, built by the web build into build/web/.
#include <filesystem>
#include <memory>
#include <string>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/web_dir.hpp"
#include "io/atomic_write.hpp"
#include "io/input_error.hpp"
#include "io/json_input.hpp"

namespace scantrace::cli {
namespace {

struct ExploreArgs {
  std::string output = "explorer.html";
};

void run_explore(const ExploreArgs& args) {
  // The page the web build assembled (web/make_explorer.mjs) in this build tree.
  const std::filesystem::path page = std::filesystem::path(kWebBuildDir) / "explorer.html";
  if (!std::filesystem::is_regular_file(page))
    throw InputError(page.string(), "",
                     "the explorer page is not built: build with SCANTRACE_BUILD_WEB=ON (the "
                     "default of scripts/build.sh) or run scripts/build.sh --web");
  const std::string html = json_input::read_text_file(page);
  write_file_atomically(args.output, html);
  spdlog::info("wrote {} ({:.2f} MB): open it in a browser, from disk or any static host", args.output,
               static_cast<double>(html.size()) / 1e6);
}

}  // namespace

Command add_explore_command(CLI::App& app) {
  auto args = std::make_shared<ExploreArgs>();
  CLI::App* cmd = app.add_subcommand(
      "explore",
      "Writes the explorer: one self-contained HTML page (no network, works from\n"
      "file://) running scantrace's own fill compiled to WebAssembly. Drag a\n"
      "triangle's vertices on the pixel grid and watch the edge table, the active\n"
      "edge list and the spans change; step with the keys of 'step'; click a pixel\n"
      "for its 'why'; open a scene (.json, .obj) and drop an image rendered for it\n"
      "for a 'diff'. The state is in the address, to link a step.");
  cmd->add_option("-o,--output", args->output, "the page to write")->capture_default_str();
  cmd->footer(
      "Examples:\n"
      "  scantrace explore -o explorer.html && xdg-open explorer.html\n"
      "Exit status: 0, 1 the page is not built (the web build is off), 2 usage.");
  return {cmd, [args] { run_explore(*args); }};
}

}  // namespace scantrace::cli
