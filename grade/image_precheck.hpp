#pragma once
// The one pre-check of a submitted image file against the scene it is compared with, made before
// any decoder runs: by `scantrace diff` (cli/diff_command.cpp), by the Python package's diff() of
// a file (python/src: the .npy reader and the OpenCV module's image reader) and by the
// WebAssembly module's diff() and checkImage() (web/bindings_grade.cpp). In this order:
//   1. the header: a .npy's shape, an image file's declared size (PNG IHDR, BMP, JPEG), within
//      what can be compared (2^28 pixels);
//   2. that size against the scene's canvas: when it is not the canvas's, the header alone
//      answers (`canvas_size`, canvas_size_report) and nothing more is read or decoded — a
//      746 KB PNG declaring 16000x16000 was decoded (6 GB, 8-16 s) against a 32x32 scene only to
//      be reported the wrong size. The one exception is the canvas with width and
//      height swapped: whether the image is transposed only its pixels say, and it has as many
//      pixels as the canvas;
//   3. the memory its decoding needs (io/memory_budget.hpp) and a PNG's chunks
//      (check_before_decoding).
#include <cstdint>
#include <string>
#include <string_view>

#include "grade/diff_report.hpp"
#include "grade/image_header.hpp"

namespace scantrace::grade {

struct ImageHeader {
  std::string format;  // "png", "bmp", "jpeg", "npy"
  std::int64_t width = 0, height = 0;
};

// How an executable reads an image file's declared size: declared_png_or_bmp_size
// (image_header.hpp) where libjpeg is not linked, declared_size (image_input.hpp) where it is.
using DeclaredSizeReader = bool (*)(std::string_view bytes, const std::string& name,
                                    std::int64_t& width, std::int64_t& height,
                                    std::string& format);

// Whether the declared size alone decides the comparison (step 2 above).
bool size_decides(std::int64_t width, std::int64_t height, int canvas_width, int canvas_height);

// Steps 1-3 for the file `bytes` (named `name` in messages) against a canvas_width x
// canvas_height scene; `header` receives what the header says. True: the header decides (report
// canvas_size_report, decode nothing); false: the file may be decoded. Throws InputError (not an
// image, a broken header, too large for the memory, a truncated PNG).
bool precheck_image(std::string_view bytes, const std::string& name, DeclaredSizeReader read_size,
                    int canvas_width, int canvas_height, ImageHeader& header);

// What `diff` reports of an image whose header decided: the global mistake `canvas_size`, the
// image's declared size, no pixel compared (a note says why), and the reference for diff.png.
DiffReport canvas_size_report(const Scene& scene, const FillOptions& options,
                              const ImageHeader& header, const DiffOptions& diff_options);

}  // namespace scantrace::grade
