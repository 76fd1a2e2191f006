// A PNG of a few dozen bytes can declare 100000×100000 pixels: its reader refuses it from the
// header, before the decoder allocates for it (io/image_size.hpp).
#include <cstdint>
#include <cstdlib>
#include <string>

#include <catch2/catch.hpp>

#include "cli_test_support.hpp"
#include "io/image_size.hpp"
#include "io/input_error.hpp"
#include "viz/image_file.hpp"

using namespace scantrace;
using namespace scantrace::test;

namespace {

std::string be32(std::uint32_t v) {
  return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
          static_cast<char>(v)};
}

// The signature and an IHDR chunk declaring width × height, 8-bit RGB; no pixel data follows.
std::string png_header(std::uint32_t width, std::uint32_t height) {
  return std::string("\x89PNG\r\n\x1a\n", 8) + be32(13) + "IHDR" + be32(width) + be32(height) +
         std::string("\x08\x02\x00\x00\x00", 5) + be32(0);
}

}  // namespace

TEST_CASE("the declared size of a PNG is read from its header", "[image][robustness]") {
  const auto size = png_declared_size(png_header(100000, 70000));
  REQUIRE(size.has_value());
  CHECK(size->width == 100000);
  CHECK(size->height == 70000);
  CHECK(png_declared_size(png_header(0x80000000u, 1))->width == 2147483648LL);
  CHECK_FALSE(png_declared_size(std::string("GIF89a")).has_value());
  CHECK_FALSE(png_declared_size(png_header(5, 5).substr(0, 23)).has_value());
}

TEST_CASE("a PNG declaring 100000x100000 pixels is refused before decoding",
          "[image][robustness]") {
  TempDir dir;
  write_text(dir / "huge.png", png_header(100000, 100000));
  CHECK_THROWS_AS(read_png(dir / "huge.png"), InputError);
  CHECK_THROWS_WITH(read_png(dir / "huge.png"),
                    (dir / "huge.png").string() +
                        ": the image declares 100000x100000 pixels, more than the limit of 2^28 "
                        "pixels; refused before decoding");
  write_text(dir / "empty.png", png_header(0, 10));
  CHECK_THROWS_WITH(read_png(dir / "empty.png"), Catch::Contains("0x10 pixels: it has no pixel"));
  // Within the pixel limit, but not within the memory there is: 16000 × 16000 × 15 bytes.
  write_text(dir / "big.png", png_header(16000, 16000));
  ::setenv("SCANTRACE_MAX_MEMORY", "64M", 1);
  CHECK_THROWS_WITH(read_png(dir / "big.png"),
                    Catch::Contains("decoding the 16000x16000 image needs about 3.6 GiB, more "
                                    "than the 64 MiB of memory available"));
  ::unsetenv("SCANTRACE_MAX_MEMORY");
  // A real image still reads.
  RgbImage small(3, 2, Rgb32f{0.25f, 0.5f, 1.0f});
  write_png(small, dir / "small.png");
  const RgbImage back = read_png(dir / "small.png");
  CHECK(back.width() == 3);
  CHECK(back.height() == 2);
}
