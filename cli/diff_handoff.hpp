#pragma once
// `scantrace-diff`'s JPEG and BMP images: it links no OpenCV (cli/diff_main.cpp), so a command
// line whose IMAGE is one of them is handed, unchanged, to `scantrace-tools` beside it, the same
// `diff` command with OpenCV's decoders (grade/opencv_decode.hpp).
#include <string_view>

#include "grade/image_header.hpp"

namespace scantrace::cli {

// The command line to hand over; main() records it before running the command.
void keep_diff_command_line(int argc, char** argv);

// scantrace-diff's JpegBmpDecoder (grade/image_header.hpp): runs scantrace-tools on the kept
// command line, and so never returns when that starts; throws InputError naming the image when
// it cannot.
void hand_image_to_scantrace_tools(std::string_view bytes, grade::SubmittedImage& image);

}  // namespace scantrace::cli
