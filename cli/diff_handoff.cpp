#include "cli/diff_handoff.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "cli/handoff.hpp"
#include "io/input_error.hpp"

namespace scantrace::cli {
namespace {
char** kept_argv = nullptr;
}  // namespace

void keep_diff_command_line(int, char** argv) {
  kept_argv = argv;
}

// Nothing has been written yet when the image is read (the scene is loaded, no output is), so
// the other executable starts the command again from the beginning; its start-up (OpenCV's
// codecs, ~0.1-0.3 s) is paid by JPEG and BMP images only.
void hand_image_to_scantrace_tools(std::string_view, grade::SubmittedImage& out) {
  std::error_code ec;
  const std::filesystem::path tools =
      beside_this_executable("scantrace-tools", kept_argv ? kept_argv[0] : "");
  std::string why = "cannot be found";
  if (kept_argv != nullptr && std::filesystem::exists(tools, ec)) {
    std::fflush(nullptr);
    execv(tools.c_str(), kept_argv);
    why = std::string("cannot be run (") + std::strerror(errno) + ")";
  }
  throw InputError(out.name, "",
                   "a " + out.format + " image is decoded by scantrace-tools (OpenCV), which " +
                       why + " beside " + tools.parent_path().string() + "; PNG and .npy images need none");
}

}  // namespace scantrace::cli
