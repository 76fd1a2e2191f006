#pragma once
// `scantrace-diff`'s JPEG and BMP images: it links no OpenCV (cli/diff_main.cpp), so a command
// line whose IMAGE is one of them is handed, unchanged, to `scantrace-tools` beside it, the same
// `diff` command with OpenCV's decoders (grade/opencv_decode.hpp is the seam).
namespace scantrace::cli {

// The command line to hand over; main() records it before running the command.
void keep_diff_command_line(int argc, char** argv);

}  // namespace scantrace::cli
