#pragma once
// The subcommands of the `scantrace` binary (docs/design.md §7). Each add_*_command registers its
// options on the app and returns the action to run once the whole command line has parsed, so
// that parsing (usage errors, exit status 2) and running (bad input, exit status 1) stay apart.
#include <functional>

#include "cli/demo_explain.hpp"
#include "grade/image_header.hpp"

namespace CLI {
class App;
}

namespace scantrace::cli {

struct Command {
  CLI::App* app = nullptr;
  // Throws InputError for bad input data, another std::exception for any other failure.
  std::function<void()> run;
};

Command add_render_command(CLI::App& app);
// `explain`: the demo's last step, which differs by executable (cli/demo_explain.hpp).
Command add_demo_command(CLI::App& app, ExplainDemo explain);
Command add_trace_command(CLI::App& app);
Command add_replay_command(CLI::App& app);
Command add_explain_command(CLI::App& app);
Command add_stress_command(CLI::App& app);
Command add_bench_command(CLI::App& app);
Command add_check_command(CLI::App& app);
Command add_why_command(CLI::App& app);
// `jpeg_bmp`: the executable's decoder of JPEG and BMP images (grade/image_header.hpp).
Command add_diff_command(CLI::App& app, grade::JpegBmpDecoder jpeg_bmp);
Command add_explore_command(CLI::App& app);  // the web build's explorer page (web/)
Command add_grade_command(CLI::App& app);

// The subcommands scantrace-tools has and `scantrace` alone does not (every one but demo and
// render, cli/main.cpp): the demo's build names them as left out (cli/main_render.cpp). A cli
// test compares this list with scantrace-tools' --help.
inline constexpr const char* kToolsOnlyCommands[]{"trace", "replay",  "explain", "check",
                                                  "step",  "stress",  "bench",   "why",
                                                  "diff",  "explore", "grade"};

// Thrown by a command that ran to the end but must exit with a status of its own (diff: the images
// differ); main() returns `status` without printing anything more.
struct ExitStatus {
  int status = 0;
};
inline constexpr int kExitImagesDiffer = 3;
Command add_step_command(CLI::App& app);

}  // namespace scantrace::cli
