#pragma once
// Where a command line goes (docs/architecture.md, "Executables"). `scantrace` runs `render`
// itself and passes every other command line, unchanged, once: `grade` to python3 (the grader),
// `diff` to scantrace-diff unless it names a JPEG or BMP file (then to scantrace-tools, whose
// OpenCV decodes it), anything else to scantrace-tools. scantrace-diff, run by hand on a JPEG or
// BMP image, passes its command line on to scantrace-tools (cli/diff_handoff.hpp).
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace scantrace::cli {

// The executable `name` in this executable's directory (or argv0's, when /proc/self/exe cannot be
// read); it may not exist.
std::filesystem::path beside_this_executable(std::string_view name, const char* argv0);

// Whether an argument in argv[from, argc) is an existing file that starts like a JPEG or BMP.
// An output file's name that happens to match only sends the command to scantrace-tools, which
// runs the same diff: the choice changes how fast the command starts, never what it does.
bool names_jpeg_or_bmp_file(int argc, char** argv, int from);

// Runs the grader (`python3 -m scantrace.grade ARGS`, python/scantrace/grade/) in place of this
// process, with the scantrace package found beside the executable; exits 1 when it cannot start.
[[noreturn]] void run_grader(const std::vector<std::string>& args);

}  // namespace scantrace::cli
