// The one pre-check of a submitted image against the scene (grade/image_precheck.hpp, issue 46
// #16): a header declaring a size other than the canvas's is answered `canvas_size` from the
// header alone — the decoder is never called — and only a size that matches (or is the canvas
// transposed) goes on to the memory budget and the decoder.
#include <chrono>
#include <cstdint>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "../cli/cli_test_support.hpp"
#include "grade/image_input.hpp"
#include "grade/image_precheck.hpp"
#include "io/input_error.hpp"
#include "io/scene_json.hpp"
#include "wrong_renderers.hpp"

using namespace gradetest;
using scantrace::test::run_scantrace;
using scantrace::test::TempDir;

namespace {

std::string be32(std::uint32_t v) {
  return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
          static_cast<char>(v)};
}
std::string le32(std::uint32_t v) {
  return {static_cast<char>(v), static_cast<char>(v >> 8), static_cast<char>(v >> 16),
          static_cast<char>(v >> 24)};
}

// A PNG of a few dozen bytes declaring width x height, 8-bit RGB: IHDR, an IDAT of one byte (no
// decoder gets a row out of it: decoded, it is an error) and IEND. CRCs are zero: libpng would
// refuse them too.
std::string tiny_png(std::uint32_t width, std::uint32_t height) {
  return std::string("\x89PNG\r\n\x1a\n", 8) + be32(13) + "IHDR" + be32(width) + be32(height) +
         std::string("\x08\x02\x00\x00\x00", 5) + be32(0) + be32(1) + "IDAT" + "x" + be32(0) +
         be32(0) + "IEND" + be32(0);
}

// A Windows BMP header declaring width x height, 24 bits, and no pixels.
std::string tiny_bmp(std::uint32_t width, std::uint32_t height) {
  std::string b = "BM" + le32(54) + le32(0) + le32(54) + le32(40) + le32(width) + le32(height);
  b += std::string("\x01\x00\x18\x00", 4) + std::string(24, '\0');
  return b;
}

// A JpegBmpDecoder that counts its calls and decodes nothing: the image stays as the pre-check
// left it (a canvas-sized image of zeros, so the diff still runs).
int decoder_calls = 0;
void counting_decoder(std::string_view, scantrace::grade::SubmittedImage& out) {
  ++decoder_calls;
  out.pixels = scantrace::RgbImage(200, 160);
}

bool has_global(const scantrace::grade::DiffReport& r, const std::string& kind) {
  for (const auto& g : r.global)
    if (g.kind == kind) return true;
  return false;
}

}  // namespace

TEST_CASE("pre-check: a header of another size is answered canvas_size, nothing decoded",
          "[grade][image][precheck]") {
  namespace grade = scantrace::grade;
  TempDir dir;
  const scantrace::Scene s = generated_scene();  // 200 x 160
  REQUIRE(s.width == 200);
  REQUIRE(s.height == 160);
  const scantrace::FillOptions o;
  // 16000 x 16000 (2^27.9 pixels: within the pixel limit, 3.6 GiB to decode) and one pixel
  // more than the canvas: both answered from the header; the decoder is never called.
  for (const auto& [w, h] : {std::pair{16000u, 16000u}, std::pair{201u, 160u}}) {
    INFO(w << "x" << h);
    scantrace::test::write_text(dir / "big.bmp", tiny_bmp(w, h));
    decoder_calls = 0;
    const grade::DiffReport r = grade::diff_image_file(s, o, dir / "big.bmp", &counting_decoder, {});
    CHECK(decoder_calls == 0);
    CHECK(has_global(r, "canvas_size"));
    CHECK(r.global.size() == 1);
    CHECK(r.image_width == static_cast<int>(w));
    CHECK(r.image_height == static_cast<int>(h));
    CHECK(r.compared_pixels == 0);
    CHECK_FALSE(r.agrees());
    CHECK(r.category_map.size() == 200u * 160u);
  }
  // The canvas's size, and the canvas transposed (only pixels say whether it is transposed): the
  // decoder is called.
  for (const auto& [w, h] : {std::pair{200u, 160u}, std::pair{160u, 200u}}) {
    INFO(w << "x" << h);
    scantrace::test::write_text(dir / "ok.bmp", tiny_bmp(w, h));
    decoder_calls = 0;
    grade::diff_image_file(s, o, dir / "ok.bmp", &counting_decoder, {});
    CHECK(decoder_calls == 1);
  }
  // The pixel limit is the header's own: 100000 x 100000 is still refused, not compared.
  scantrace::test::write_text(dir / "huge.bmp", tiny_bmp(100000, 100000));
  CHECK_THROWS_WITH(grade::diff_image_file(s, o, dir / "huge.bmp", &counting_decoder, {}),
                    Catch::Contains("outside what can be compared"));
  // The rule by itself.
  CHECK_FALSE(grade::size_decides(200, 160, 200, 160));
  CHECK_FALSE(grade::size_decides(160, 200, 200, 160));
  CHECK(grade::size_decides(200, 200, 200, 160));
  CHECK(grade::size_decides(199, 160, 200, 160));
}

TEST_CASE("pre-check: a .npy of another shape is answered from its header, its values unread",
          "[grade][image][precheck]") {
  namespace grade = scantrace::grade;
  // A float32 .npy of shape (10, 12, 3) whose values are NaN: read, they are an error.
  std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (10, 12, 3), }";
  while ((10 + header.size() + 1) % 64) header += ' ';
  header += '\n';
  std::string npy = std::string("\x93NUMPY\x01\x00", 8) + static_cast<char>(header.size()) + '\0' +
                    header + std::string(10 * 12 * 3 * 4, '\xff');
  grade::ImageHeader h;
  CHECK(grade::precheck_image(npy, "x.npy", &grade::declared_png_or_bmp_size, 200, 160, h));
  CHECK(h.format == "npy");
  CHECK(h.width == 12);
  CHECK(h.height == 10);
  // Against its own size it is not decided, and decoding it is the NaN error.
  CHECK_FALSE(grade::precheck_image(npy, "x.npy", &grade::declared_png_or_bmp_size, 12, 10, h));
  CHECK_THROWS_WITH(grade::decode_npy(npy, "x.npy"), Catch::Contains("NaN"));
}

TEST_CASE("diff of a 16000x16000 PNG header against a 200x160 scene: canvas_size in under 2 s",
          "[grade][cli][precheck]") {
  TempDir dir;
  scantrace::save_scene(generated_scene(), dir / "scene.json");
  scantrace::test::write_text(dir / "big.png", tiny_png(16000, 16000));
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = run_scantrace(dir.path(), {"-q", "diff", "scene.json", "big.png", "--json"}, 30);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  INFO(r.err);
  // Decoded, the one-byte IDAT would have been an error (exit 1): 3 is a diff that differs.
  CHECK(r.exit_code == 3);
  CHECK(seconds < 2);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  REQUIRE(j["global"].size() == 1);
  CHECK(j["global"][0]["kind"] == "canvas_size");
  CHECK(j["global"][0]["text"] == "the image is 16000x16000, the scene's canvas is 200x160");
  CHECK(j["image"]["width"] == 16000);
  CHECK(j["compared_pixels"] == 0);
  CHECK(j["agrees"] == false);
}
