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
#include <optional>
#include <string>
#include <string_view>

#include "grade/image_header.hpp"
#include "grade/image_precheck.hpp"

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

// Reads `file` through the pre-check against a canvas_width x canvas_height scene
// (image_precheck.hpp, JPEG headers included): the decoded image, or nullopt when the header
// decides (`header` then says the declared size; nothing was decoded). Throws InputError.
std::optional<SubmittedImage> read_submitted_image(const std::filesystem::path& file,
                                                   JpegBmpDecoder jpeg_bmp, int canvas_width,
                                                   int canvas_height, ImageHeader& header);

// `file` compared with the scene as `scantrace diff` compares them: canvas_size_report when the
// header decides, else the decoded image's diff. Throws InputError.
DiffReport diff_image_file(const Scene& scene, const FillOptions& options,
                           const std::filesystem::path& file, JpegBmpDecoder jpeg_bmp,
                           const DiffOptions& diff_options);

}  // namespace scantrace::grade
