// `scantrace-diff`: `scantrace diff` alone (docs/architecture.md, "Executables"). `scantrace`
// hands a `diff` command line here rather than to `scantrace-tools`, whose video and window
// parts (OpenCV's videoio and highgui, 260 shared libraries with imgcodecs) cost 0.3-0.5 s of
// dynamic loading before any work. This executable links no OpenCV at all: a PNG is decoded by
// libpng (grade/png_decoder.hpp), a .npy by io/npy_reader.hpp, diff.png drawn and written without
// it (grade/diff_image.cpp); a JPEG or BMP command line goes on to `scantrace-tools`
// (cli/diff_handoff.hpp). `scantrace-tools diff` is the same command.
#include "cli/app.hpp"
#include "cli/diff_handoff.hpp"
#include "cli/scene_input.hpp"
#include "io/mat_scene.hpp"

int main(int argc, char** argv) {
  using namespace scantrace::cli;
  read_mat_scenes_with(scantrace::load_mat_scene);
  keep_diff_command_line(argc, argv);
  constexpr AddCommand commands[]{
      [](CLI::App& app) { return add_diff_command(app, hand_image_to_scantrace_tools); }};
  return run_app(argc, argv, commands);
}
