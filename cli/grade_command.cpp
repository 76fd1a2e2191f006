// scantrace grade SUBMISSION…: the autograder. One implementation, in Python
// (python/scantrace/grade/, `python3 -m scantrace.grade`): this subcommand hands it the whole
// command line, options and --help included, and its exit status is the grader's.
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/handoff.hpp"

namespace scantrace::cli {

Command add_grade_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "grade",
      "Grades students' triangle-filling code (vector_interp, f_shading, g_shading,\n"
      "render_img) in a sandbox and names each mistake as a cause; Gradescope\n"
      "results.json, Markdown and HTML reports, a class report. Runs\n"
      "'python3 -m scantrace.grade' with the same arguments: 'scantrace grade --help'\n"
      "lists its options (docs/grading.md).");
  // Everything after `grade`, --help included, is the grader's.
  cmd->set_help_flag();
  cmd->prefix_command();
  cmd->fallthrough(false);
  return {cmd, [cmd] { run_grader(cmd->remaining()); }};
}

}  // namespace scantrace::cli
