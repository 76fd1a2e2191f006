// The strict .npy reader: what np.save writes is read exactly; everything else is one clear error.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

#include <catch2/catch.hpp>

#include "grade/image_input.hpp"
#include "io/input_error.hpp"
#include "io/json_input.hpp"
#include "io/npy_reader.hpp"

using scantrace::InputError;
using scantrace::parse_npy;

namespace {

// A .npy file as np.save writes it (version 1.0, header padded to a multiple of 64 bytes).
std::string npy(const std::string& descr, const std::string& shape, const std::string& data,
                const std::string& fortran = "False") {
  std::string header =
      "{'descr': '" + descr + "', 'fortran_order': " + fortran + ", 'shape': " + shape + ", }";
  while ((10 + header.size() + 1) % 64) header += ' ';
  header += '\n';
  std::string out = "\x93NUMPY";
  out += '\x01';
  out += '\x00';
  out += static_cast<char>(header.size() & 0xFF);
  out += static_cast<char>(header.size() >> 8);
  return out + header + data;
}

template <class T>
std::string bytes(std::initializer_list<T> values) {
  std::string out;
  for (T v : values) out.append(reinterpret_cast<const char*>(&v), sizeof v);
  return out;
}

std::string error_of(const std::string& file) {
  try {
    parse_npy(file, "img.npy");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("npy: float32, float64 and uint8 H×W×3 arrays are read exactly", "[grade][npy]") {
  const auto f4 = parse_npy(
      npy("<f4", "(1, 2, 3)", bytes<float>({0.f, 0.25f, 0.5f, 1.f, 0.125f, 0.75f})), "a.npy");
  CHECK(f4.height == 1);
  CHECK(f4.width == 2);
  CHECK_FALSE(f4.integer);
  CHECK(f4.values == std::vector<float>{0.f, 0.25f, 0.5f, 1.f, 0.125f, 0.75f});
  const auto f8 =
      parse_npy(npy("<f8", "(2, 1, 3)", bytes<double>({0.1, 0.2, 0.3, 0.4, 0.5, 0.6})), "b.npy");
  CHECK(f8.height == 2);
  CHECK(f8.values[5] == 0.6f);
  const auto u1 = parse_npy(npy("|u1", "(1, 1, 3)", std::string("\x00\x80\xff", 3)), "c.npy");
  CHECK(u1.integer);
  CHECK(u1.values == std::vector<float>{0.f, 128.f, 255.f});
  const auto image = scantrace::grade::decode_image(
      npy("|u1", "(1, 1, 3)", std::string("\x00\x80\xff", 3)), "c.npy", nullptr);
  CHECK(image.pixels(0, 0).g == Approx(128.0 / 255));
}

TEST_CASE("npy: integer arrays of any width are 8-bit values, checked to be 0..255",
          "[grade][npy]") {
  // np.round(255 * img).astype(int) saved: int64 (and int32, uint16, int8) hold 8-bit values.
  const auto i8 = parse_npy(npy("<i8", "(1, 1, 3)", bytes<std::int64_t>({0, 128, 255})), "d.npy");
  CHECK(i8.integer);
  CHECK(i8.values == std::vector<float>{0.f, 128.f, 255.f});
  const auto u2 = parse_npy(npy("<u2", "(1, 1, 3)", bytes<std::uint16_t>({7, 8, 9})), "e.npy");
  CHECK(u2.values == std::vector<float>{7.f, 8.f, 9.f});
  const auto image = scantrace::grade::decode_image(
      npy("<i4", "(1, 1, 3)", bytes<std::int32_t>({0, 128, 255})), "f.npy", nullptr);
  CHECK(image.eight_bit);
  CHECK(image.pixels(0, 0).g == Approx(128.0 / 255));
  CHECK(error_of(npy("<i4", "(1, 2, 3)", bytes<std::int32_t>({0, 0, 0, 1, 300, 2}))) ==
        "img.npy: pixel [0][1]: value 300 is not 0..255 (an integer image holds 8-bit values; a "
        "float image, colours in [0, 1])");
  CHECK(error_of(npy("|i1", "(1, 1, 3)", std::string("\x01\xff\x02", 3))).find("value -1") !=
        std::string::npos);
}

TEST_CASE("npy: bad inputs are one line naming the file and the field", "[grade][npy]") {
  CHECK(error_of(npy("|O", "(1, 1, 3)", "")).find("pickles") != std::string::npos);
  CHECK(error_of(npy(">i4", "(1, 1, 3)", std::string(12, '\0'))).find("dtype '>i4'") !=
        std::string::npos);
  CHECK(error_of(npy("<c8", "(1, 1, 3)", std::string(24, '\0'))).find("dtype '<c8'") !=
        std::string::npos);
  CHECK(error_of(npy(">f4", "(1, 1, 3)", std::string(12, '\0'))).find("dtype '>f4'") !=
        std::string::npos);
  CHECK(error_of(npy("<f4", "(4, 3)", std::string(48, '\0'))).find("shape (4, 3)") !=
        std::string::npos);
  CHECK(error_of(npy("<f4", "(1, 1, 4)", std::string(16, '\0'))).find("not H×W×3") !=
        std::string::npos);
  CHECK(error_of(npy("<f4", "(1, 1, 3)", std::string(12, '\0'), "True")).find("Fortran") !=
        std::string::npos);
  CHECK(error_of(npy("<f4", "(2, 2, 3)", std::string(20, '\0'))).find("needs 48") !=
        std::string::npos);
  CHECK(error_of(npy("<f4", "(100000, 100000, 3)", "")).find("more than") != std::string::npos);
  CHECK(error_of("not a numpy file at all").find("magic") != std::string::npos);
  CHECK(error_of(npy("<f4", "(1, 1, 3)", "").substr(0, 20)).find("truncated") != std::string::npos);
  const std::string nan = error_of(npy(
      "<f4", "(1, 2, 3)", bytes<float>({0, 0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0})));
  CHECK(nan.find("pixel [0][1]") != std::string::npos);
  CHECK(nan.find("NaN") != std::string::npos);
  for (const std::string& e : {error_of(npy("|O", "(1, 1, 3)", "")), nan}) {
    CHECK(e.rfind("img.npy: ", 0) == 0);
    CHECK(e.find('\n') == std::string::npos);
  }
}

TEST_CASE("image files: a huge declared size and a truncated PNG are refused before decoding",
          "[grade][image]") {
  // A PNG signature and an IHDR declaring 100000 x 100000 pixels.
  std::string png(
      "\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR\x00\x01\x86\xa0\x00\x01\x86\xa0\x08\x02\x00\x00\x00",
      29);
  png += std::string(4, '\0');  // CRC (not checked before the size)
  png += std::string("\x00\x00\x00\x00IEND\xae\x42\x60\x82", 12);
  try {
    scantrace::grade::decode_image(png, "huge.png", nullptr);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("100000x100000") != std::string::npos);
  }
  // The same header declaring 5 x 5, cut inside its chunks (the size is checked first).
  std::string small = png;
  small.replace(16, 8, std::string("\x00\x00\x00\x05\x00\x00\x00\x05", 8));
  try {
    scantrace::grade::decode_image(small.substr(0, 40), "cut.png", nullptr);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("truncated") != std::string::npos);
  }
  CHECK_THROWS_AS(scantrace::grade::decode_image("GIF89a....", "x.gif", nullptr), InputError);
}

TEST_CASE("image files: a declared size whose product overflows 64 bits is refused, not wrapped",
          "[grade][image][robustness]") {
  // fuzz/regressions/image_input/png-size-overflow (found by fuzz_image_input in CI): an IHDR of
  // 4294902015 x 4278190082. Their product, 2^63.99, overflowed the signed 64-bit check (UBSan),
  // and a wrapped product could pass it.
  const std::string png =
      scantrace::json_input::read_text_file(std::filesystem::path(SCANTRACE_SOURCE_DIR) /
                                            "fuzz/regressions/image_input/png-size-overflow");
  try {
    scantrace::grade::decode_image(png, "overflow.png", nullptr);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("declares 4294902015x4278190082 pixels") != std::string::npos);
  }
}
