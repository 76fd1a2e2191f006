// Any bytes given as the IMAGE of `scantrace diff` — a .npy array (io/npy_reader.hpp) or a PNG,
// JPEG or BMP file (grade/image_input.hpp) — either decode or throw InputError; nothing else may
// escape (another exception, a crash, a sanitizer report, a hang, a huge allocation: declared
// sizes are checked before anything is decoded).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "grade/image_input.hpp"
#include "grade/opencv_decode.hpp"
#include "io/input_error.hpp"

// The fuzzer runs under -rss_limit_mb=2048: a header declaring a large image must be refused by the
// memory check, not decoded into an out-of-memory report.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  setenv("SCANTRACE_MAX_MEMORY", "256M", 1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const auto image =
        scantrace::grade::decode_image(bytes, "fuzz.img", scantrace::grade::decode_with_opencv);
    // What was accepted has a shape and finite values.
    if (image.pixels.width() <= 0 || image.pixels.height() <= 0) __builtin_trap();
  } catch (const scantrace::InputError&) {
  }
  return 0;
}
