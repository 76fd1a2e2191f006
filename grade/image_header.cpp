#include "grade/image_header.hpp"

#include "io/input_error.hpp"
#include "io/memory_budget.hpp"
#include "io/npy_reader.hpp"
#include "src/scene.hpp"

namespace scantrace::grade {
namespace {

std::uint32_t be32(std::string_view b, std::size_t at) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(b[at])) << 24 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 1])) << 16 |
         static_cast<std::uint32_t>(static_cast<unsigned char>(b[at + 2])) << 8 |
         static_cast<unsigned char>(b[at + 3]);
}
std::int32_t le32(std::string_view b, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = v << 8 | static_cast<unsigned char>(b[at + k]);
  return static_cast<std::int32_t>(v);
}

// Refuses a canvas of more than 2^28 pixels, or one whose decoding needs more memory than there
// is (`bytes_per_pixel`: the decoder's buffer and the float copy together).
void check_pixels(std::int64_t w, std::int64_t h, std::uint64_t bytes_per_pixel,
                  const std::string& name, const std::string& element) {
  check_pixel_limit(w, h, name, element);
  check_memory(static_cast<std::uint64_t>(w * h) * bytes_per_pixel,
               "decoding the " + std::to_string(w) + "x" + std::to_string(h) + " image", name,
               element);
}

// The chunks of a PNG walked from the signature to IEND: each must lie inside the file. Bytes
// after IEND are accepted (libpng stops reading there; some tools append metadata), a walk that
// runs out first is a truncated file (which would otherwise decode partly).
void check_png_chunks(std::string_view b, const std::string& name) {
  for (std::size_t at = 8;;) {
    if (b.size() - at < 12)
      throw InputError(name, "PNG data", "the file is truncated (it ends before its IEND chunk)");
    const std::uint64_t length = be32(b, at);
    if (length > 0x7FFFFFFF)
      throw InputError(name, "PNG chunk at byte " + std::to_string(at),
                       "declares " + std::to_string(length) + " bytes (at most 2^31 - 1)");
    if (b.substr(at + 4, 4) == "IEND") return;
    if (length + 12 > b.size() - at)
      throw InputError(name, "PNG data", "the file is truncated (it ends inside a chunk)");
    at += static_cast<std::size_t>(length) + 12;
  }
}

// BMP sizes where OpenCV's decoder reads them: an OS/2 (BITMAPCOREHEADER, 12 bytes) header holds
// 16-bit sizes at 18 and 20, the Windows headers (40 bytes and more) 32-bit ones at 18 and 22.
// Reading an OS/2 file as Windows refused a valid one as "declares 33554944x1572865".
void bmp_size(std::string_view b, const std::string& name, std::int64_t& width,
              std::int64_t& height) {
  if (b.size() < 18) throw InputError(name, "BMP header", "truncated header");
  const std::int32_t header = le32(b, 14);
  if (header == 12) {
    if (b.size() < 26) throw InputError(name, "BMP header", "truncated header");
    width = static_cast<std::uint16_t>(le32(b, 18) & 0xFFFF);
    height = static_cast<std::uint16_t>(le32(b, 20) & 0xFFFF);
    return;
  }
  if (b.size() < 26) throw InputError(name, "BMP header", "truncated header");
  width = le32(b, 18), height = le32(b, 22);
  if (height < 0) height = -height;
}

}  // namespace

void check_pixel_limit(std::int64_t w, std::int64_t h, const std::string& name,
                       const std::string& element) {
  // Each side first: two 32-bit sides can multiply past 2^63.
  if (w <= 0 || h <= 0 || w > kMaxCanvasPixels || h > kMaxCanvasPixels || w * h > kMaxCanvasPixels)
    throw InputError(name, element,
                     "declares " + std::to_string(w) + "x" + std::to_string(h) +
                         " pixels, outside what can be compared (at most 2^28 pixels)");
}

bool is_npy(std::string_view bytes) {
  return bytes.size() >= 6 && bytes.substr(0, 6) == "\x93NUMPY";
}

bool declared_png_or_bmp_size(std::string_view b, const std::string& name, std::int64_t& width,
                              std::int64_t& height, std::string& format) {
  if (b.size() >= 8 && b.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8)) {
    format = "png";
    // IHDR must be the first chunk; libpng reads the size from exactly these bytes.
    if (b.size() < 24 || b.substr(12, 4) != "IHDR")
      throw InputError(name, "PNG header", "truncated or missing IHDR chunk");
    width = be32(b, 16), height = be32(b, 20);
    return true;
  }
  if (b.size() >= 2 && b[0] == 'B' && b[1] == 'M') {
    format = "bmp";
    bmp_size(b, name, width, height);
    return true;
  }
  return false;
}

void check_before_decoding(std::string_view bytes, const std::string& name, std::int64_t width,
                           std::int64_t height, const std::string& format) {
  // A .npy is converted straight into the float image (decode_npy); an image file's decoded
  // bytes come first, then the float copy.
  if (format == "npy") return check_pixels(width, height, sizeof(Rgb32f), name, "npy header shape");
  check_pixels(width, height, 3 + sizeof(Rgb32f), name, format + " header");
  if (format == "png") check_png_chunks(bytes, name);
}

// A .npy image goes through the same pixel limit and memory budget as an image file (it did
// not: 8000x8000x3 uint8 took 1.72 GB under a 500 MB budget), and is converted straight into
// the float image, with no float copy of the whole array on the way.
SubmittedImage decode_npy(std::string_view bytes, const std::string& name) {
  const NpyLayout npy = parse_npy_layout(bytes, name, kMaxNpyImageBytes);
  check_before_decoding(bytes, name, npy.width, npy.height, "npy");
  SubmittedImage out;
  out.name = name;
  out.format = "npy";
  out.eight_bit = npy.integer;
  out.pixels = RgbImage(npy.width, npy.height);
  const float scale = npy.integer ? 1.0f / 255.0f : 1.0f;
  std::size_t k = 0;
  for (int y = 0; y < npy.height; ++y)
    for (int x = 0; x < npy.width; ++x, k += 3)
      out.pixels(x, y) = {npy_value(npy, bytes, k, name) * scale,
                          npy_value(npy, bytes, k + 1, name) * scale,
                          npy_value(npy, bytes, k + 2, name) * scale};
  return out;
}

}  // namespace scantrace::grade
