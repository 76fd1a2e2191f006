#pragma once
// The PNG writer of `scantrace render` and of the libraries' write_png (viz/image_file.hpp): the
// container written here, the rows compressed by libdeflate. A render that loads no OpenCV starts
// in milliseconds, where OpenCV's image codecs bring in 260 shared libraries and 140 ms of
// dynamic linking before main() (docs/performance.md, "The one-shot command"); reading images
// and writing videos stay on OpenCV.
#include <filesystem>
#include <string>

#include "src/image.hpp"

namespace scantrace::png {

// Writes `image` as an 8-bit RGB PNG, each channel round(255·c) clamped (to_byte, as
// viz/image_file.hpp's write_png), under a temporary name renamed into place: a failed or
// interrupted write never leaves a truncated file. Throws std::runtime_error naming the file.
void write(const RgbImage& image, const std::filesystem::path& file);

// The PNG file's bytes, as write() writes them (the SVG frames embed their canvas cells so).
std::string encode(const RgbImage& image);

}  // namespace scantrace::png
