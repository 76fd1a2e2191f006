// PNG files: 8-bit rounding, RGB/BGR order at the OpenCV boundary, atomic writes.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <catch2/catch.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli_test_support.hpp"
#include "io/input_error.hpp"
#include "src/splitmix64.hpp"
#include "viz/image_file.hpp"
#include "viz/opencv_image.hpp"

using namespace scantrace;
using scantrace::test::TempDir;

namespace {

float expected_channel(float c) {
  const double v = std::round(255.0 * std::clamp(static_cast<double>(c), 0.0, 1.0));
  return static_cast<float>(v) / 255.0f;
}

}  // namespace

TEST_CASE("to_byte rounds 255*c to nearest and clamps", "[image_file]") {
  CHECK(to_byte(0.0f) == 0);
  CHECK(to_byte(1.0f) == 255);
  CHECK(to_byte(0.5f) == 128);  // 127.5 rounds up
  CHECK(to_byte(0.2f) == 51);
  CHECK(to_byte(1.0f / 3.0f) == 85);
  CHECK(to_byte(-0.25f) == 0);
  CHECK(to_byte(7.0f) == 255);
  CHECK(to_byte(std::numeric_limits<float>::quiet_NaN()) == 0);
}

TEST_CASE("write_png then read_png gives round(255c)/255", "[image_file]") {
  TempDir dir;
  const float values[] = {0.0f, 1.0f, 0.5f, 0.2f, 1.0f / 3.0f, 0.999f, 0.001f, 0.7f, -0.5f, 1.5f};
  RgbImage image(5, 3);
  int k = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x, ++k)
      image(x, y) = {values[k % 10], values[(k + 3) % 10], values[(k + 7) % 10]};

  write_png(image, dir / "out.png");
  const RgbImage back = read_png(dir / "out.png");
  REQUIRE(back.width() == 5);
  REQUIRE(back.height() == 3);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      INFO("pixel (" << x << ", " << y << ")");
      CHECK(back(x, y).r == expected_channel(image(x, y).r));
      CHECK(back(x, y).g == expected_channel(image(x, y).g));
      CHECK(back(x, y).b == expected_channel(image(x, y).b));
    }
  CHECK(test::file_names(dir.path()) == std::vector<std::string>{"out.png"});
}

TEST_CASE("PNG channels are in BGR order for OpenCV, RGB for us", "[image_file]") {
  TempDir dir;
  RgbImage image(4, 2, Rgb32f{1, 1, 1});
  image(1, 0) = {1, 0, 0};  // red
  image(2, 1) = {0, 0, 1};  // blue
  write_png(image, dir / "red.png");

  const RgbImage back = read_png(dir / "red.png");
  CHECK(back(1, 0) == Rgb32f{1, 0, 0});
  CHECK(back(2, 1) == Rgb32f{0, 0, 1});
  CHECK(back(0, 0) == Rgb32f{1, 1, 1});

  const cv::Mat bgr = cv::imread((dir / "red.png").string(), cv::IMREAD_UNCHANGED);
  REQUIRE(bgr.type() == CV_8UC3);
  REQUIRE(bgr.cols == 4);
  REQUIRE(bgr.rows == 2);
  CHECK(bgr.at<cv::Vec3b>(0, 1) == cv::Vec3b(0, 0, 255));  // at(row, col)
  CHECK(bgr.at<cv::Vec3b>(1, 2) == cv::Vec3b(255, 0, 0));
  CHECK(bgr.at<cv::Vec3b>(0, 0) == cv::Vec3b(255, 255, 255));
}

TEST_CASE("write_png replaces an existing file and leaves nothing on failure", "[image_file]") {
  TempDir dir;
  const auto file = dir / "out.png";
  write_png(RgbImage(2, 2, Rgb32f{0, 0, 0}), file);
  write_png(RgbImage(3, 1, Rgb32f{1, 1, 1}), file);
  CHECK(read_png(file).width() == 3);
  CHECK(test::file_names(dir.path()) == std::vector<std::string>{"out.png"});

  // A directory that does not exist: the error names the file.
  const auto missing = dir / "no-such-dir" / "out.png";
  CHECK_THROWS_WITH(write_png(RgbImage(2, 2), missing),
                    Catch::StartsWith(missing.string() + ": cannot create file"));
  // The target is a directory: the complete temporary cannot be renamed over it, and is removed.
  std::filesystem::create_directory(dir / "taken.png");
  CHECK_THROWS_WITH(write_png(RgbImage(2, 2), dir / "taken.png"),
                    Catch::StartsWith((dir / "taken.png").string() + ": cannot write"));
  CHECK(test::file_names(dir.path()) == std::vector<std::string>{"out.png", "taken.png"});
  CHECK_THROWS_WITH(write_png(RgbImage(), dir / "empty.png"), Catch::Contains("empty.png"));
}

// The container is written by io/png_writer.cpp itself (signature, IHDR, IDAT, IEND, each with
// its CRC) around libdeflate's stream: libpng, through OpenCV, reads it back, checking every
// CRC and the stream's Adler-32, on sizes from one pixel to a stream of several IDAT chunks.
TEST_CASE("write_png's files decode, pixel for pixel, in libpng", "[image_file]") {
  TempDir dir;
  SplitMix64 rng(21);
  // {width, height, noisy}: noise does not compress, so 800×700 needs two 1 MiB IDAT chunks.
  const struct {
    int w, h;
    bool noise;
  } sizes[] = {{1, 1, false}, {1, 9, true}, {9, 1, true}, {33, 17, false}, {800, 700, true}};
  for (const auto& [w, h, noise] : sizes) {
    INFO(w << "x" << h);
    RgbImage image(w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        image(x, y) = noise ? Rgb32f{static_cast<float>(rng.unit()), static_cast<float>(rng.unit()),
                                     static_cast<float>(rng.unit())}
                            : Rgb32f{x / float(w), y / float(h), (x + y) % 3 / 2.0f};
    write_png(image, dir / "out.png");
    const cv::Mat bgr = cv::imread((dir / "out.png").string(), cv::IMREAD_UNCHANGED);
    REQUIRE(bgr.type() == CV_8UC3);
    REQUIRE(bgr.cols == w);
    REQUIRE(bgr.rows == h);
    int wrong = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        wrong += bgr.at<cv::Vec3b>(y, x) !=
                 cv::Vec3b(to_byte(image(x, y).b), to_byte(image(x, y).g), to_byte(image(x, y).r));
    CHECK(wrong == 0);
  }
}

TEST_CASE("read_png reports unreadable files as input errors", "[image_file]") {
  TempDir dir;
  CHECK_THROWS_AS(read_png(dir / "missing.png"), InputError);
  test::write_text(dir / "text.png", "not a png");
  CHECK_THROWS_WITH(read_png(dir / "text.png"), Catch::Contains("text.png"));
}
