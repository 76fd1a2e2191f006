#pragma once
// Image files. The canvas holds float RGB in [0, 1]; files hold 8-bit channels, round(255·c)
// clamped to [0, 255] (docs/design.md §2). OpenCV (reading) and libpng (writing,
// io/png_writer.hpp) stay behind this header.
#include <filesystem>

#include "src/image.hpp"

namespace scantrace {

// Writes `image` as an 8-bit RGB PNG. The file is written under a temporary name and renamed
// into place, so a failed or interrupted write never leaves a truncated PNG. Throws
// std::runtime_error naming the file on failure.
void write_png(const RgbImage& image, const std::filesystem::path& file);

// Reads an image file (any format OpenCV decodes) back as float RGB, each channel byte / 255.
// Throws InputError naming the file when it cannot be read.
RgbImage read_png(const std::filesystem::path& file);

}  // namespace scantrace
