// `scantrace-diff`: `scantrace diff` alone (docs/architecture.md, "Executables"). `scantrace`
// hands a `diff` command line here rather than to `scantrace-tools`, whose video and window
// parts (OpenCV's videoio and highgui, 260 shared libraries with imgcodecs) cost 0.3-0.5 s of
// dynamic loading before any work; this executable links OpenCV's core, imgproc and imgcodecs
// only (the submitted image's decoding, diff.png). `scantrace-tools diff` is the same command.
#include "cli/app.hpp"

int main(int argc, char** argv) {
  using namespace scantrace::cli;
  constexpr AddCommand commands[]{add_diff_command};
  return run_app(argc, argv, commands);
}
