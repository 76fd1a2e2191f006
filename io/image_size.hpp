#pragma once
// The size an image file declares, read from its header before anything is decoded, and the guard
// every reader of user images calls with it: a 200-byte PNG can declare 100000×100000 pixels, and
// a decoder trusting it allocates 30 GB (or the caller's float copy 120 GB) before finding out the
// pixels are not there. Used by read_png (viz/image_file.hpp) and meant for every image input
// (`diff`'s too).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace scantrace {

struct DeclaredImageSize {
  std::int64_t width = 0, height = 0;
};

// Width and height of the IHDR chunk of a PNG (its first 24 bytes), nullopt when `bytes` does not
// start like a PNG.
std::optional<DeclaredImageSize> png_declared_size(std::string_view bytes);
// The same for a file (reads its first 24 bytes only); nullopt when it is not a PNG.
std::optional<DeclaredImageSize> read_png_declared_size(const std::filesystem::path& file);

// Throws InputError("<file>: image of WxH pixels ...") when the image has no pixel, more than
// kMaxCanvasPixels (2^28) pixels, or needs more than the memory available at `bytes_per_pixel`
// (the decoder's buffer and the caller's copy together).
void check_image_size(const DeclaredImageSize& size, std::uint64_t bytes_per_pixel,
                      const std::string& file);

}  // namespace scantrace
