#pragma once
// The IMAGE of `scantrace diff`: what someone else's renderer produced. An 8-bit PNG (decoded by
// libpng, grade/png_decoder.hpp), JPEG or BMP (by the decoder the caller
// passes, JpegBmpDecoder: OpenCV's, grade/opencv_decode.hpp), or a NumPy
// .npy array H×W×3 (io/npy_reader.hpp). The size an image file declares in its header is checked
// against the memory available before anything is decoded, so a PNG declaring 100000×100000 is
// refused with one line instead of exhausting the machine. The checks and the .npy decoding, which
// need no OpenCV nor libpng (the WebAssembly module has them), are in grade/image_header.hpp.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "grade/image_header.hpp"

namespace scantrace::grade {

// The size declared by a PNG (IHDR), BMP (Windows or OS/2 header) or JPEG (its frame header as
// libjpeg reads it: grade/jpeg_header.hpp); false when `bytes` is none of them or too short to
// say. Throws InputError for a header that is recognised but broken.
bool declared_size(std::string_view bytes, const std::string& name, std::int64_t& width,
                   std::int64_t& height, std::string& format);

// Decodes an image file held in memory (the fuzz target's entry): a PNG or .npy here, a JPEG or
// BMP by `jpeg_bmp` (image_header.hpp). Throws InputError.
SubmittedImage decode_image(std::string_view bytes, const std::string& name,
                            JpegBmpDecoder jpeg_bmp);

// Reads `file`: a .npy by its magic or extension, an image file otherwise. Throws InputError.
SubmittedImage read_submitted_image(const std::filesystem::path& file, JpegBmpDecoder jpeg_bmp);

}  // namespace scantrace::grade
