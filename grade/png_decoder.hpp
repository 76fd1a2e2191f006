#pragma once
// A submitted PNG decoded with libpng itself, not through OpenCV's imgcodecs: `scantrace-diff`
// then loads no OpenCV at all for a PNG or a .npy (imgcodecs brings Debian's codecs, GDAL among
// them, ~140 shared libraries and most of the process's start-up; docs/grading.md, "Speed").
// The transforms are the ones OpenCV's PNG decoder applies for cv::IMREAD_COLOR, so both give
// the same pixels (tests/grade/test_png_decoder.cpp compares them): 16-bit samples keep their
// high byte, alpha and tRNS are dropped (not composited), palettes and grey expanded to RGB,
// interlacing undone, no gamma applied.
#include <string>
#include <string_view>

#include "src/image.hpp"

namespace scantrace::grade {

// `bytes` is a whole PNG file whose IHDR size was already checked against the memory budget
// (image_input.cpp). Returns RGB as bytes / 255. libpng's warnings (a bad CRC in an ancillary
// chunk, say) are appended to `warnings`. Throws InputError naming `name` and what libpng said.
RgbImage decode_png(std::string_view bytes, const std::string& name, std::string& warnings);

}  // namespace scantrace::grade
