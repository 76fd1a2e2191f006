// scantrace grade SUBMISSION…: the autograder. One implementation, in Python
// (python/scantrace/grade/, `python3 -m scantrace.grade`): this subcommand hands it the whole
// command line, options and --help included, and its exit status is the grader's.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"

namespace scantrace::cli {
namespace {

namespace fs = std::filesystem;

// Where the scantrace Python package is: $SCANTRACE_PYTHONPATH, else beside this executable in
// the build tree (build/cli/ -> build/python/) or in its install prefix (bin/ ->
// lib/python3/dist-packages/); else wherever python3 finds it.
std::string package_dir() {
  if (const char* env = std::getenv("SCANTRACE_PYTHONPATH")) return env;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  for (const fs::path& dir : {exe.parent_path().parent_path() / "python",
                              exe.parent_path().parent_path() / "lib/python3/dist-packages"})
    if (fs::exists(dir / "scantrace/grade/__main__.py", ec)) return dir.string();
  return {};
}

[[noreturn]] void run(const std::vector<std::string>& args) {
  const std::string dir = package_dir();
  if (!dir.empty()) {
    const char* old = std::getenv("PYTHONPATH");
    const std::string path = old && *old ? dir + ":" + old : dir;
    setenv("PYTHONPATH", path.c_str(), 1);
  }
  // Debian's interpreter: its numpy is the one deps.sh installs (a python3 earlier in PATH may
  // have none); SCANTRACE_PYTHON overrides.
  const char* python = std::getenv("SCANTRACE_PYTHON");
  if (!python) python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  std::vector<const char*> argv{python, "-m", "scantrace.grade"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  argv.push_back(nullptr);
  std::fflush(stdout);
  execvp(python, const_cast<char* const*>(argv.data()));
  std::fprintf(stderr, "scantrace grade: error: cannot run %s: %s\n", python,
               std::strerror(errno));
  std::exit(1);
}

}  // namespace

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
  return {cmd, [cmd] { run(cmd->remaining()); }};
}

}  // namespace scantrace::cli
