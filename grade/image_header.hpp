#pragma once
// What is checked of a submitted image file before any decoder sees it, and the .npy arrays,
// which need no decoder: no OpenCV, no libjpeg, so the WebAssembly module (web/) refuses a bad
// image with the command's own line before the browser decodes it. The image decoders, and the
// JPEG header as libjpeg reads it, are in grade/image_input.hpp.
#include <cstdint>
#include <string>
#include <string_view>

#include "src/image.hpp"
#include "src/scene.hpp"

namespace scantrace::grade {

struct SubmittedImage {
  RgbImage pixels;        // RGB as the file holds it: bytes / 255, or the .npy values unscaled
  std::string format;     // "png", "jpeg", "bmp" or "npy"
  bool eight_bit = true;  // channel values are multiples of 1/255 (image files, uint8 arrays)
  std::string name;       // for messages
};

// Decodes what libpng and the .npy reader do not, a JPEG or a BMP (out.format says which, its
// declared size already checked), into out.pixels; throws InputError naming out.name. Each
// executable passes its own to decode_image (grade/image_input.hpp): OpenCV's imgcodecs where it
// is linked (grade/opencv_decode.hpp), handing the command to scantrace-tools in scantrace-diff,
// which links no OpenCV (cli/diff_handoff.hpp); nullptr where no decoder exists (the image is
// then refused with one line naming its format).
using JpegBmpDecoder = void (*)(std::string_view bytes, SubmittedImage& out);

// The most data a .npy image may declare: 2^28 pixels of three float64 values.
inline constexpr std::uint64_t kMaxNpyImageBytes = 8 * 3 * static_cast<std::uint64_t>(kMaxCanvasPixels);

// A NumPy .npy file, by its magic.
bool is_npy(std::string_view bytes);

// The size declared by a PNG (IHDR) or BMP (Windows or OS/2 header); false when `bytes` is
// neither or too short to say (a JPEG's: declared_size in image_input.hpp). Throws InputError for
// a header that is recognised but broken.
bool declared_png_or_bmp_size(std::string_view bytes, const std::string& name, std::int64_t& width,
                              std::int64_t& height, std::string& format);

// A declared size within what can be compared (2^28 pixels, both sides positive): a property of
// the header alone, checked before anything else. Throws InputError.
void check_pixel_limit(std::int64_t width, std::int64_t height, const std::string& name,
                       const std::string& element);

// The checks made before an image file of `format` ("npy" too) declaring width × height is
// decoded: the size within the pixel limit and the memory available (the decoded bytes and the
// float copy), and a PNG's chunks inside the file (a truncated one would otherwise decode partly).
// Throws InputError. (Against a scene, grade/image_precheck.hpp's precheck_image runs it.)
void check_before_decoding(std::string_view bytes, const std::string& name, std::int64_t width,
                           std::int64_t height, const std::string& format);

// A .npy array H×W×3 (io/npy_reader.hpp) as the submitted image, through the same pixel limit and
// memory budget as an image file. Throws InputError.
SubmittedImage decode_npy(std::string_view bytes, const std::string& name);

}  // namespace scantrace::grade
