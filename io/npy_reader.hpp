#pragma once
// A small, strict reader of NumPy .npy files (format versions 1.0, 2.0, 3.0): the course's Python
// renderers save their canvas with np.save as an H×W×3 array of float32/float64 in [0, 1] or of
// uint8. Only that is accepted: little-endian (or byte-order free) float32, float64 or uint8, C
// order, three dimensions with 3 channels last, no pickled objects. Anything else is an InputError
// naming the file and the header field, never a crash or a guess.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace scantrace {

struct NpyImage {
  int height = 0, width = 0;
  std::string dtype;          // "<f4", "<f8", "|u1", "<i8", … (as written in the header)
  bool integer = false;       // an integer dtype: values are 0..255
  std::vector<float> values;  // height·width·3, row-major, RGB as stored (not scaled)
};

// The header of a .npy file: its dtype string, order and shape (any dtype, object arrays too),
// and where the data begins. Throws InputError for a file that is not .npy or a broken header.
struct NpyHeader {
  std::string descr;
  bool fortran = false;
  std::vector<std::uint64_t> shape;
  std::size_t data_offset = 0;
};
NpyHeader parse_npy_header(std::string_view bytes, const std::string& name);

// The header of a .npy file, checked: dtype, shape, and a data part of exactly the declared size.
struct NpyLayout {
  int height = 0, width = 0;
  std::string dtype;
  bool integer = false;   // an integer dtype: 8-bit values 0..255 (any width)
  bool is_signed = false;  // of an integer dtype
  std::size_t item = 0;    // bytes per value: 1, 2, 4 or 8
  std::size_t data = 0;  // offset of the first value
  std::size_t values() const { return static_cast<std::size_t>(height) * width * 3; }
};

// Checks the header of `bytes` (throws InputError naming `name` and the header field); the data
// it declares may not exceed `max_bytes`. Nothing is allocated for the values.
NpyLayout parse_npy_layout(std::string_view bytes, const std::string& name,
                           std::uint64_t max_bytes = std::uint64_t{1} << 32);

// Value k (0-based, row-major, channels last) as the float32 it is compared as; InputError naming
// the pixel for NaN, an infinity, or a float64 beyond float32's range.
float npy_value(const NpyLayout& layout, std::string_view bytes, std::size_t k,
                const std::string& name);

// Parses the bytes of a .npy file; `name` is used in error messages. Throws InputError.
// `max_bytes` caps the declared data size before anything is allocated.
NpyImage parse_npy(std::string_view bytes, const std::string& name,
                   std::uint64_t max_bytes = std::uint64_t{1} << 32);

}  // namespace scantrace
