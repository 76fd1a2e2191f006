#pragma once
// JPEG and BMP images, decoded by OpenCV's imgcodecs (decode_image hands them here; a PNG is
// decoded by libpng itself, grade/png_decoder.hpp, and a .npy by io/npy_reader.hpp).
//
// The JpegBmpDecoder (grade/image_header.hpp) of every executable that links OpenCV;
// `scantrace-diff`, which links none so that it starts without loading imgcodecs' ~140 libraries,
// passes one that hands the whole command line to `scantrace-tools` (cli/diff_handoff.hpp).
#include <string_view>

#include "grade/image_input.hpp"

namespace scantrace::grade {

// Fills out.pixels from `bytes`, an image of out.format ("jpeg" or "bmp") whose declared size was
// checked already. Throws InputError naming out.name.
void decode_with_opencv(std::string_view bytes, SubmittedImage& out);

}  // namespace scantrace::grade
