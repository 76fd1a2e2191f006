// `scantrace-tools`: every subcommand of `scantrace` (docs/design.md §7). The `scantrace`
// executable runs `render` itself and hands every other command line to this one
// (cli/main_render.cpp).
#include "cli/app.hpp"
#include "cli/scene_input.hpp"
#include "grade/opencv_decode.hpp"
#include "io/mat_scene.hpp"

int main(int argc, char** argv) {
  using namespace scantrace::cli;
  read_mat_scenes_with(scantrace::load_mat_scene);
  // kToolsOnlyCommands (cli/commands.hpp) names the commands after demo and render: keep the two
  // in step (a cli test compares it with this executable's --help).
  constexpr AddCommand commands[]{
      [](CLI::App& app) { return add_demo_command(app, explain_demo_with_video); },
      add_render_command,
      add_trace_command,
      add_replay_command,
      add_explain_command,
      add_stress_command,
      add_bench_command,
      add_check_command,
      add_why_command,
      [](CLI::App& app) { return add_diff_command(app, scantrace::grade::decode_with_opencv); },
      add_step_command,
      add_explore_command,
      add_grade_command};
  return run_app(argc, argv, commands);
}
