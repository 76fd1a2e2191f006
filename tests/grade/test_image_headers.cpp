// The size a submitted image declares is the one its decoder reads (issue 37 #10), and what the
// file formats allow is accepted (#17: bytes after a PNG's IEND, an OS/2 BMP); a float64 .npy
// value beyond float32 is refused, not turned into an infinity (#4).
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <opencv2/imgcodecs.hpp>

#include "grade/image_input.hpp"
#include "grade/opencv_decode.hpp"
#include "io/input_error.hpp"
#include "io/npy_reader.hpp"

using scantrace::InputError;

namespace {

std::string encoded(const std::string& ext, const cv::Mat& image) {
  std::vector<unsigned char> out;
  REQUIRE(cv::imencode(ext, image, out));
  return std::string(out.begin(), out.end());
}

cv::Mat test_image(int w, int h) {
  cv::Mat m(h, w, CV_8UC3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      m.at<cv::Vec3b>(y, x) =
          cv::Vec3b(static_cast<unsigned char>(x * 40), static_cast<unsigned char>(y * 50), 200);
  return m;
}

}  // namespace

TEST_CASE("image headers: a JPEG's size is libjpeg's, whatever a marker's false length says",
          "[grade][image][robustness]") {
  std::string jpeg = encoded(".jpg", test_image(16, 16));
  // The real frame is made to declare 3000 x 3000.
  const std::size_t sof = jpeg.find("\xff\xc0");
  REQUIRE(sof != std::string::npos);
  jpeg[sof + 5] = '\x0b', jpeg[sof + 6] = '\xb8', jpeg[sof + 7] = '\x0b', jpeg[sof + 8] = '\xb8';
  // After SOI, a TEM marker (FF01, which has no length) followed by two bytes a marker walker
  // takes for its length, pointing past EOI to a fake frame header declaring 1 x 1.
  const std::size_t fake_at = jpeg.size() + 4;
  const std::size_t length = fake_at - 4;
  REQUIRE(length < 0xFF00);
  jpeg.insert(2, std::string{'\xff', '\x01', static_cast<char>(length >> 8),
                             static_cast<char>(length & 0xFF)});
  REQUIRE(jpeg.size() == fake_at);
  jpeg += std::string(
      "\xff\xc0\x00\x11\x08\x00\x01\x00\x01\x03\x01\x22\x00\x02\x11\x01\x03\x11\x01", 19);
  std::int64_t w = 0, h = 0;
  std::string format;
  REQUIRE(scantrace::grade::declared_size(jpeg, "tem.jpg", w, h, format));
  CHECK(format == "jpeg");
  CHECK(w == 3000);
  CHECK(h == 3000);
  // Decoding it would take 3000² x 15 bytes: over a 64 MiB budget it is refused by that size.
  ::setenv("SCANTRACE_MAX_MEMORY", "64M", 1);
  try {
    scantrace::grade::decode_image(jpeg, "tem.jpg", scantrace::grade::decode_with_opencv);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("tem.jpg") && Catch::Contains("64 MiB"));
  }
  ::unsetenv("SCANTRACE_MAX_MEMORY");
  // Not a JPEG past its signature: libjpeg's reason, in the one line.
  try {
    scantrace::grade::decode_image(std::string("\xff\xd8\xff\xd9", 4), "empty.jpg",
                                   scantrace::grade::decode_with_opencv);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK_THAT(std::string(e.what()), Catch::StartsWith("empty.jpg: JPEG header: cannot be read"));
  }
}

TEST_CASE("image headers: bytes after a PNG's IEND are accepted, a PNG cut short is not",
          "[grade][image][robustness]") {
  const cv::Mat m = test_image(5, 4);
  const std::string png = encoded(".png", m);
  const auto image = scantrace::grade::decode_image(png + "trailing bytes\n", "t.png", nullptr);
  REQUIRE(image.pixels.width() == 5);
  REQUIRE(image.pixels.height() == 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 5; ++x) {
      const cv::Vec3b bgr = m.at<cv::Vec3b>(y, x);
      CHECK(image.pixels(x, y).r == bgr[2] / 255.0f);
      CHECK(image.pixels(x, y).b == bgr[0] / 255.0f);
    }
  // Cut inside IDAT, and cut before IEND's tag: both truncated.
  for (const std::size_t keep : {png.size() - 20, png.size() - 12}) {
    CAPTURE(keep);
    try {
      scantrace::grade::decode_image(png.substr(0, keep), "cut.png", nullptr);
      FAIL("no error");
    } catch (const InputError& e) {
      CHECK_THAT(std::string(e.what()), Catch::Contains("truncated"));
    }
  }
}

TEST_CASE("image headers: an OS/2 BMP's 16-bit size is read as such",
          "[grade][image][robustness]") {
  // 2 x 2, 24 bits, BITMAPCOREHEADER (12 bytes); rows bottom-up, padded to 4 bytes, BGR.
  std::string bmp = "BM";
  const auto u16 = [&](unsigned v) {
    bmp += static_cast<char>(v & 0xFF), bmp += static_cast<char>(v >> 8);
  };
  const auto u32 = [&](unsigned v) { u16(v & 0xFFFF), u16(v >> 16); };
  u32(14 + 12 + 2 * 8), u16(0), u16(0), u32(14 + 12);
  u32(12), u16(2), u16(2), u16(1), u16(24);
  // Bottom row: blue, white; top row: red, green.
  bmp += std::string("\xff\x00\x00\xff\xff\xff\x00\x00", 8);
  bmp += std::string("\x00\x00\xff\x00\xff\x00\x00\x00", 8);
  std::int64_t w = 0, h = 0;
  std::string format;
  REQUIRE(scantrace::grade::declared_size(bmp, "os2.bmp", w, h, format));
  CHECK(w == 2);
  CHECK(h == 2);
  const auto image =
      scantrace::grade::decode_image(bmp, "os2.bmp", scantrace::grade::decode_with_opencv);
  REQUIRE(image.pixels.width() == 2);
  CHECK(image.pixels(0, 0).r == 1.0f);  // red, top left
  CHECK(image.pixels(1, 0).g == 1.0f);  // green
  CHECK(image.pixels(0, 1).b == 1.0f);  // blue, bottom left
  CHECK(image.pixels(0, 1).r == 0.0f);
  CHECK(image.pixels(1, 1).r == 1.0f);  // white
}

TEST_CASE("npy: a float64 beyond float32's range is refused, naming the pixel",
          "[grade][npy][robustness]") {
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (1, 2, 3), }";
  while ((10 + header.size() + 1) % 64) header += ' ';
  header += '\n';
  std::string file =
      std::string("\x93NUMPY\x01\x00", 8) + static_cast<char>(header.size()) + '\0' + header;
  for (const double v : {0.5, 0.25, 0.125, 0.5, 1e39, 0.5}) {
    char b[8];
    std::memcpy(b, &v, 8);
    file.append(b, 8);
  }
  try {
    scantrace::grade::decode_image(file, "big.npy", nullptr);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK_THAT(std::string(e.what()),
               Catch::Contains("big.npy: pixel [0][1]") && Catch::Contains("float32"));
  }
  CHECK_THROWS_AS(scantrace::parse_npy(file, "big.npy"), InputError);
}

// The JPEG and BMP decoder is the caller's (grade/image_header.hpp's JpegBmpDecoder):
// scantrace-diff passes one that hands the command to scantrace-tools, everything linking OpenCV
// passes OpenCV's. A PNG or .npy never reaches it; without one, a BMP is refused in one line naming
// its format.
namespace {
int decoder_calls = 0;
void one_grey_pixel(std::string_view, scantrace::grade::SubmittedImage& out) {
  ++decoder_calls;
  out.pixels = scantrace::RgbImage(1, 1);
  out.pixels(0, 0) = {0.5f, 0.5f, 0.5f};
}
}  // namespace

TEST_CASE("image input: JPEG and BMP go to the caller's decoder, PNG and .npy never do",
          "[grade][image]") {
  const cv::Mat m = test_image(3, 2);
  decoder_calls = 0;
  const auto bmp = scantrace::grade::decode_image(encoded(".bmp", m), "a.bmp", one_grey_pixel);
  CHECK(decoder_calls == 1);
  CHECK(bmp.format == "bmp");
  CHECK(bmp.pixels(0, 0).g == 0.5f);
  const auto jpeg = scantrace::grade::decode_image(encoded(".jpg", m), "a.jpg", one_grey_pixel);
  CHECK(decoder_calls == 2);
  CHECK(jpeg.format == "jpeg");
  const auto png = scantrace::grade::decode_image(encoded(".png", m), "a.png", one_grey_pixel);
  CHECK(decoder_calls == 2);  // libpng's
  CHECK(png.pixels.width() == 3);
  try {
    scantrace::grade::decode_image(encoded(".bmp", m), "b.bmp", nullptr);
    FAIL("a BMP with no decoder was accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()) == "b.bmp: a bmp image cannot be decoded here (PNG and .npy can)");
  }
}
