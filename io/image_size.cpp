#include "io/image_size.hpp"

#include <fstream>

#include "io/input_error.hpp"
#include "io/memory_budget.hpp"
#include "src/scene.hpp"

namespace scantrace {
namespace {

std::int64_t big_endian_u32(std::string_view b, std::size_t at) {
  std::int64_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(b[at + i]);
  return v;
}

}  // namespace

std::optional<DeclaredImageSize> png_declared_size(std::string_view bytes) {
  // Signature (8 bytes), then the IHDR chunk: length (4), "IHDR" (4), width (4), height (4).
  constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
  if (bytes.size() < 24 || bytes.substr(0, 8) != kSignature || bytes.substr(12, 4) != "IHDR")
    return std::nullopt;
  return DeclaredImageSize{big_endian_u32(bytes, 16), big_endian_u32(bytes, 20)};
}

std::optional<DeclaredImageSize> read_png_declared_size(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  char head[24] = {};
  in.read(head, sizeof head);
  return png_declared_size(std::string_view(head, static_cast<std::size_t>(in.gcount())));
}

void check_image_size(const DeclaredImageSize& size, std::uint64_t bytes_per_pixel,
                      const std::string& file) {
  const std::string dims = std::to_string(size.width) + "x" + std::to_string(size.height);
  if (size.width <= 0 || size.height <= 0)
    throw InputError(file, "", "the image declares " + dims + " pixels: it has no pixel");
  // Both are below 2^32 (PNG stores 31 bits), so the product fits.
  const std::uint64_t pixels =
      static_cast<std::uint64_t>(size.width) * static_cast<std::uint64_t>(size.height);
  if (pixels > static_cast<std::uint64_t>(kMaxCanvasPixels))
    throw InputError(file, "",
                     "the image declares " + dims +
                         " pixels, more than the limit of 2^28 pixels; refused before decoding");
  check_memory(pixels * bytes_per_pixel, "decoding the " + dims + " image", file, "");
}

}  // namespace scantrace
