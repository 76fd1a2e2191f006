// The PNG decoder of `diff` (grade/png_decoder.hpp: libpng, not OpenCV) against OpenCV's own
// decoder, which `diff` used before: every colour type and bit depth PNG allows, with and without
// a tRNS chunk, interlaced or not, written here by libpng's writer from random samples, must give
// the pixels cv::imdecode(IMREAD_COLOR) gives. A broken file is refused with one line naming it.
#include <png.h>

#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <opencv2/imgcodecs.hpp>

#include "grade/image_input.hpp"
#include "io/input_error.hpp"

using scantrace::InputError;

namespace {

struct PngLayout {
  int colour, depth;
  bool trns, interlaced;
};

int channels(int colour) {
  switch (colour) {
    case PNG_COLOR_TYPE_GRAY_ALPHA:
      return 2;
    case PNG_COLOR_TYPE_RGB:
      return 3;
    case PNG_COLOR_TYPE_RGB_ALPHA:
      return 4;
    default:
      return 1;  // grey, palette
  }
}

void append(png_structp png, png_bytep data, std::size_t n) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), n);
}

// A w×h PNG of random samples in `layout` (libpng's writer packs sub-byte samples itself).
std::string random_png(const PngLayout& l, int w, int h, std::mt19937& rng) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  std::string out;
  REQUIRE(setjmp(png_jmpbuf(png)) == 0);
  png_set_write_fn(png, &out, append, nullptr);
  png_set_IHDR(png, info, w, h, l.depth, l.colour,
               l.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  const int levels = 1 << std::min(l.depth, 8);
  std::vector<png_color> palette(static_cast<std::size_t>(levels));
  std::vector<png_byte> alpha(palette.size());
  for (auto& c : palette)
    c = {static_cast<png_byte>(rng()), static_cast<png_byte>(rng()), static_cast<png_byte>(rng())};
  for (auto& a : alpha) a = static_cast<png_byte>(rng());
  if (l.colour == PNG_COLOR_TYPE_PALETTE)
    png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
  png_color_16 key{};
  key.gray = key.red = 1, key.green = 2, key.blue = 3;
  if (l.trns) png_set_tRNS(png, info, alpha.data(), static_cast<int>(alpha.size()), &key);
  png_write_info(png, info);
  png_set_packing(png);                  // one byte per sub-byte sample in the rows below
  if (l.depth == 16) png_set_swap(png);  // the rows hold little-endian 16-bit samples
  const int bytes_per_sample = l.depth == 16 ? 2 : 1;
  const std::size_t row_bytes = static_cast<std::size_t>(w) * channels(l.colour) * bytes_per_sample;
  std::vector<png_byte> pixels(row_bytes * h);
  for (std::size_t k = 0; k < pixels.size(); ++k)
    pixels[k] =
        static_cast<png_byte>(l.depth < 8 && bytes_per_sample == 1 ? rng() % levels : rng() % 256);
  std::vector<png_bytep> rows(h);
  for (int y = 0; y < h; ++y) rows[y] = pixels.data() + row_bytes * y;
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

}  // namespace

TEST_CASE("png decoder: every colour type and depth decodes as OpenCV's IMREAD_COLOR does",
          "[grade][image]") {
  std::mt19937 rng(35);
  const std::vector<std::pair<int, std::vector<int>>> types{{PNG_COLOR_TYPE_GRAY, {1, 2, 4, 8, 16}},
                                                            {PNG_COLOR_TYPE_PALETTE, {1, 2, 4, 8}},
                                                            {PNG_COLOR_TYPE_RGB, {8, 16}},
                                                            {PNG_COLOR_TYPE_GRAY_ALPHA, {8, 16}},
                                                            {PNG_COLOR_TYPE_RGB_ALPHA, {8, 16}}};
  int cases = 0;
  for (const auto& [colour, depths] : types)
    for (const int depth : depths)
      for (const bool interlaced : {false, true})
        for (const bool trns : {false, true}) {
          if (trns && (colour & PNG_COLOR_MASK_ALPHA)) continue;  // PNG allows no tRNS there
          const PngLayout layout{colour, depth, trns, interlaced};
          const std::string png = random_png(layout, 13, 7, rng);
          INFO("colour type " << colour << ", depth " << depth << ", tRNS " << trns
                              << ", interlaced " << interlaced);
          const auto ours = scantrace::grade::decode_image(png, "t.png", nullptr);
          const cv::Mat cv_image =
              cv::imdecode(std::vector<unsigned char>(png.begin(), png.end()), cv::IMREAD_COLOR);
          REQUIRE(cv_image.type() == CV_8UC3);
          REQUIRE(ours.pixels.width() == cv_image.cols);
          REQUIRE(ours.pixels.height() == cv_image.rows);
          int differing = 0;
          for (int y = 0; y < cv_image.rows; ++y)
            for (int x = 0; x < cv_image.cols; ++x) {
              const cv::Vec3b b = cv_image.at<cv::Vec3b>(y, x);
              const auto p = ours.pixels(x, y);
              differing += p.r != b[2] / 255.0f || p.g != b[1] / 255.0f || p.b != b[0] / 255.0f;
            }
          CHECK(differing == 0);
          ++cases;
        }
  CHECK(cases == 2 * (5 + 4 + 2) * 2 + 2 * 2 * 2);
}

TEST_CASE("png decoder: corrupt image data is one error naming the file", "[grade][image]") {
  std::mt19937 rng(7);
  std::string png = random_png({PNG_COLOR_TYPE_RGB, 8, false, false}, 40, 30, rng);
  const std::size_t idat = png.find("IDAT");
  REQUIRE(idat != std::string::npos);
  png[idat + 8] ^= 0x5A;  // inside the compressed stream: its CRC no longer matches
  try {
    scantrace::grade::decode_image(png, "broken.png", nullptr);
    FAIL("a corrupt PNG was decoded");
  } catch (const InputError& e) {
    const std::string what = e.what();
    CHECK(what.find("broken.png") != std::string::npos);
    CHECK(what.find("libpng") != std::string::npos);
    CHECK(what.find('\n') == std::string::npos);
  }
}
