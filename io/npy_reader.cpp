#include "io/npy_reader.hpp"

#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <utility>

#include "io/input_error.hpp"
#include "io/memory_budget.hpp"

namespace scantrace {
namespace {

constexpr std::string_view kMagic = "\x93NUMPY";

// The header is a Python dict literal, e.g. {'descr': '<f4', 'fortran_order': False, 'shape':
// (512, 512, 3), }. Only that grammar is accepted: string keys, and values that are strings,
// True/False or tuples of non-negative integers. (np.load would evaluate it as Python; a reader of
// untrusted files must not.)
class HeaderParser {
 public:
  HeaderParser(std::string_view text, const std::string& name) : s_(text), name_(name) {}

  void parse(std::string& descr, bool& fortran, std::vector<std::uint64_t>& shape) {
    bool have_descr = false, have_fortran = false, have_shape = false;
    expect('{');
    for (;;) {
      skip();
      if (peek() == '}') break;
      const std::string key = string_literal("header key");
      expect(':');
      skip();
      if (key == "descr") {
        if (peek() != '\'' && peek() != '"')
          fail("descr", "is not a plain dtype string (a structured or object dtype)");
        descr = string_literal("descr"), have_descr = true;
      } else if (key == "fortran_order") {
        fortran = boolean(), have_fortran = true;
      } else if (key == "shape") {
        shape = tuple(), have_shape = true;
      } else {
        fail(key, "is not a key of the .npy header");
      }
      skip();
      if (peek() == ',') ++i_;
    }
    if (!have_descr) fail("descr", "is missing from the header");
    if (!have_fortran) fail("fortran_order", "is missing from the header");
    if (!have_shape) fail("shape", "is missing from the header");
  }

 private:
  [[noreturn]] void fail(const std::string& element, const std::string& problem) const {
    throw InputError(name_, "header " + element, problem);
  }
  void skip() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\t')) ++i_;
  }
  char peek() const { return i_ < s_.size() ? s_[i_] : '\0'; }
  void expect(char c) {
    skip();
    if (peek() != c)
      fail("",
           std::string("expected '") + c + "' at byte " + std::to_string(i_) + " of the header");
    ++i_;
  }
  std::string string_literal(const char* what) {
    skip();
    const char q = peek();
    if (q != '\'' && q != '"') fail(what, "expected a quoted string");
    const std::size_t end = s_.find(q, i_ + 1);
    if (end == std::string_view::npos) fail(what, "unterminated string");
    std::string out(s_.substr(i_ + 1, end - i_ - 1));
    i_ = end + 1;
    return out;
  }
  bool boolean() {
    if (s_.substr(i_, 4) == "True") return i_ += 4, true;
    if (s_.substr(i_, 5) == "False") return i_ += 5, false;
    fail("fortran_order", "expected True or False");
  }
  std::vector<std::uint64_t> tuple() {
    expect('(');
    std::vector<std::uint64_t> out;
    for (;;) {
      skip();
      if (peek() == ')') break;
      if (!std::isdigit(static_cast<unsigned char>(peek()))) fail("shape", "expected an integer");
      std::uint64_t v = 0;
      while (std::isdigit(static_cast<unsigned char>(peek()))) {
        if (v > (std::uint64_t{1} << 40)) fail("shape", "a dimension is absurdly large");
        v = v * 10 + static_cast<std::uint64_t>(s_[i_++] - '0');
      }
      out.push_back(v);
      skip();
      if (peek() == ',') ++i_;
      if (out.size() > 8) fail("shape", "too many dimensions");
    }
    ++i_;
    return out;
  }

  std::string_view s_;
  const std::string& name_;
  std::size_t i_ = 0;
};

std::string shape_text(const std::vector<std::uint64_t>& shape) {
  std::string s = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
  return s + ")";
}

}  // namespace

NpyHeader parse_npy_header(std::string_view bytes, const std::string& name) {
  if (bytes.size() < 10 || bytes.substr(0, 6) != kMagic)
    throw InputError(name, "", "not a NumPy .npy file (the magic \\x93NUMPY is missing)");
  const auto major = static_cast<unsigned char>(bytes[6]);
  std::size_t header_len = 0, offset = 0;
  if (major == 1) {
    header_len = static_cast<unsigned char>(bytes[8]) |
                 static_cast<std::size_t>(static_cast<unsigned char>(bytes[9])) << 8;
    offset = 10;
  } else if (major == 2 || major == 3) {
    if (bytes.size() < 12) throw InputError(name, "", "truncated .npy header");
    for (int k = 3; k >= 0; --k)
      header_len = header_len << 8 | static_cast<unsigned char>(bytes[8 + k]);
    offset = 12;
  } else {
    throw InputError(name, "", "unsupported .npy format version " + std::to_string(major));
  }
  if (header_len > bytes.size() - offset)
    throw InputError(name, "",
                     "truncated .npy header (declares " + std::to_string(header_len) + " bytes)");
  NpyHeader h;
  HeaderParser(bytes.substr(offset, header_len), name).parse(h.descr, h.fortran, h.shape);
  h.data_offset = offset + header_len;
  return h;
}

// (bytes per value, signed) of a little-endian (or single-byte) integer dtype string.
static std::optional<std::pair<std::size_t, bool>> integer_descr(const std::string& d) {
  static const std::pair<const char*, std::pair<std::size_t, bool>> kTypes[] = {
      {"|u1", {1, false}}, {"<u1", {1, false}}, {"u1", {1, false}}, {"|i1", {1, true}},
      {"<i1", {1, true}},  {"i1", {1, true}},   {"<u2", {2, false}}, {"<i2", {2, true}},
      {"<u4", {4, false}}, {"<i4", {4, true}},  {"<u8", {8, false}}, {"<i8", {8, true}}};
  for (const auto& [name, type] : kTypes)
    if (d == name) return type;
  return std::nullopt;
}

NpyLayout parse_npy_layout(std::string_view bytes, const std::string& name,
                           std::uint64_t max_bytes) {
  const NpyHeader header = parse_npy_header(bytes, name);
  const std::string& descr = header.descr;
  const bool fortran = header.fortran;
  const std::vector<std::uint64_t>& shape = header.shape;

  NpyLayout out;
  if (descr == "<f4") {
    out.item = 4;
  } else if (descr == "<f8") {
    out.item = 8;
  } else if (const auto bits = integer_descr(descr)) {
    // Integers of any width hold 8-bit values (np.round(255 * img).astype(int) saved as int64);
    // each value is checked to be 0..255 as it is read (npy_value).
    out.item = bits->first, out.integer = true, out.is_signed = bits->second;
  } else if (descr == "|O" || descr == "O") {
    throw InputError(name, "header descr",
                     "object arrays (pickles) are refused; save the canvas as float or uint8");
  } else {
    throw InputError(
        name, "header descr",
        "dtype '" + descr + "' is not supported (little-endian float32, float64 or integers only)");
  }
  out.dtype = descr;
  if (fortran)
    throw InputError(name, "header fortran_order",
                     "Fortran order is not supported (save with np.ascontiguousarray)");
  if (shape.size() != 3 || shape[2] != 3)
    throw InputError(name, "header shape",
                     "shape " + shape_text(shape) + " is not H×W×3 (an RGB image)");
  if (shape[0] == 0 || shape[1] == 0 || shape[0] > 1000000 || shape[1] > 1000000)
    throw InputError(name, "header shape", "shape " + shape_text(shape) + " is out of range");
  const std::uint64_t count = shape[0] * shape[1] * 3;
  if (count * out.item > max_bytes)
    throw InputError(name, "header shape",
                     "shape " + shape_text(shape) + " declares " +
                         format_bytes(count * out.item) + ", more than the " +
                         format_bytes(max_bytes) + " allowed");
  out.data = header.data_offset;
  if (bytes.size() - out.data != count * out.item)
    throw InputError(name, "data",
                     "holds " + std::to_string(bytes.size() - out.data) + " bytes, the shape " +
                         shape_text(shape) + " needs " + std::to_string(count * out.item));
  out.height = static_cast<int>(shape[0]);
  out.width = static_cast<int>(shape[1]);
  return out;
}

// Value k of an integer array, as a double (exact for the 0..255 range that is accepted; larger
// magnitudes only need to compare outside it).
static double integer_value(const NpyLayout& layout, const char* p, std::size_t k) {
  const char* at = p + layout.item * k;
  const auto read = [at](auto zero) {
    decltype(zero) x;
    std::memcpy(&x, at, sizeof x);
    return static_cast<double>(x);
  };
  switch (layout.item) {
    case 1: return layout.is_signed ? read(std::int8_t{}) : read(std::uint8_t{});
    case 2: return layout.is_signed ? read(std::int16_t{}) : read(std::uint16_t{});
    case 4: return layout.is_signed ? read(std::int32_t{}) : read(std::uint32_t{});
    default: return layout.is_signed ? read(std::int64_t{}) : read(std::uint64_t{});
  }
}

float npy_value(const NpyLayout& layout, std::string_view bytes, std::size_t k,
                const std::string& name) {
  static_assert(std::endian::native == std::endian::little,
                "the reader assumes a little-endian host");
  const char* p = bytes.data() + layout.data;
  double v;
  if (layout.integer) {
    v = integer_value(layout, p, k);
    if (v < 0 || v > 255) {
      const std::size_t pixel = k / 3;
      throw InputError(name,
                       "pixel [" + std::to_string(pixel / layout.width) + "][" +
                           std::to_string(pixel % layout.width) + "]",
                       "value " + std::to_string(static_cast<long long>(v)) +
                           " is not 0..255 (an integer image holds 8-bit values; a float image, "
                           "colours in [0, 1])");
    }
  } else if (layout.item == 4) {
    float f;
    std::memcpy(&f, p + 4 * k, 4);
    v = f;
  } else {
    std::memcpy(&v, p + 8 * k, 8);
  }
  // Checked after the conversion to the float that is compared: a float64 above FLT_MAX is
  // finite as stored and infinite once converted (report.json then held nulls).
  const auto f = static_cast<float>(v);
  if (!std::isfinite(f)) {
    const std::size_t pixel = k / 3;
    const std::string where = "pixel [" + std::to_string(pixel / layout.width) + "][" +
                              std::to_string(pixel % layout.width) + "]";
    if (std::isnan(v)) throw InputError(name, where, "NaN");
    if (std::isinf(v)) throw InputError(name, where, "infinite value");
    throw InputError(name, where,
                     "value " + std::to_string(v) +
                         " is beyond the range of a float32 (colours are compared as float32)");
  }
  return f;
}

NpyImage parse_npy(std::string_view bytes, const std::string& name, std::uint64_t max_bytes) {
  const NpyLayout layout = parse_npy_layout(bytes, name, max_bytes);
  NpyImage out;
  out.height = layout.height, out.width = layout.width;
  out.dtype = layout.dtype;
  out.integer = layout.integer;
  out.values.resize(layout.values());
  for (std::size_t k = 0; k < out.values.size(); ++k)
    out.values[k] = npy_value(layout, bytes, k, name);
  return out;
}

}  // namespace scantrace
