// `scantrace`: the command users run. It renders itself (`scantrace render`, `--version`) and
// hands every other command line, unchanged, to the one program that runs it (cli/handoff.hpp):
// `scantrace-tools` beside it (cli/main.cpp), which has every subcommand, `scantrace-diff` or the
// grader. Where there is no scantrace-tools (the demo's build,
// scripts/build.sh --demo, which installs no OpenCV), it runs `demo` too (cli/demo_explain.hpp),
// and says of the other subcommands that the full build has them.
//
// Why two executables: the other subcommands replay traces into images, videos and windows
// through OpenCV, whose image codecs, video I/O and HighGUI bring in 260 shared libraries (GDAL,
// GDCM, FFmpeg, Qt). Loading and relocating them took 141 ms before main() on every run, where a
// render of the course scene takes 3 ms: what a student waits for, once per render. This
// executable links none of them (the PNG is written by io/png_writer.hpp on libdeflate), nor matio
// (cli/scene_input.cpp), and exec() costs the other commands a few milliseconds.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string_view>

#include <string>
#include <vector>

#include "cli/app.hpp"
#include "cli/handoff.hpp"
#include "io/mat_scene.hpp"

namespace {

// The index in argv of the subcommand word (or of --version): the first argument after the main
// app's own flags; argc when there is none.
int subcommand_index(int argc, char** argv) {
  int i = 1;
  while (i < argc && (std::string_view(argv[i]) == "-q" || std::string_view(argv[i]) == "--quiet"))
    ++i;
  return i;
}

// Whether this command line is `render` (or --version) of a scene that is not a MATLAB .mat file
// (scantrace-tools reads those: cli/scene_input.cpp).
bool runs_here(int argc, char** argv, int word) {
  if (word == argc) return false;
  const std::string_view arg = argv[word];
  if (arg == "--version") return true;
  if (arg != "render") return false;
  for (int j = word + 1; j < argc; ++j)
    if (scantrace::is_mat_file(argv[j])) return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace scantrace::cli;
  const int word = subcommand_index(argc, argv);
  if (runs_here(argc, argv, word)) {
    constexpr AddCommand render[]{add_render_command};
    return run_app(argc, argv, render);
  }
  std::error_code ec;
  const std::filesystem::path tools = beside_this_executable("scantrace-tools", argv[0]);
  if (!std::filesystem::exists(tools, ec)) {
    constexpr AddCommand here[]{
        [](CLI::App& app) { return add_demo_command(app, explain_demo_with_svg); },
        add_render_command};
    return run_app(argc, argv, here, kToolsOnlyCommands);
  }
  const std::string_view command = word < argc ? argv[word] : "";
  // The grader is Python: scantrace-tools would only start it (cli/grade_command.cpp).
  if (command == "grade") run_grader(std::vector<std::string>(argv + word + 1, argv + argc));
  // `diff` runs in scantrace-diff, which loads no video or window library (cli/diff_main.cpp),
  // unless its image is a JPEG or BMP, which only scantrace-tools' OpenCV decodes.
  if (const std::filesystem::path diff = beside_this_executable("scantrace-diff", argv[0]);
      command == "diff" && !names_jpeg_or_bmp_file(argc, argv, word + 1) &&
      std::filesystem::exists(diff, ec))
    execv(diff.c_str(), argv);
  execv(tools.c_str(), argv);
  std::fprintf(stderr, "scantrace: error: cannot run %s: %s\n", tools.c_str(),
               std::strerror(errno));
  return 1;
}
