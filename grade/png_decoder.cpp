#include "grade/png_decoder.hpp"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <vector>

#include "io/input_error.hpp"

namespace scantrace::grade {
namespace {

// What libpng's callbacks see. The error text is a fixed buffer: the error callback longjmps,
// and nothing with a destructor may live in the frames it jumps over.
struct PngSource {
  std::string_view bytes;
  std::size_t at = 0;
  char error[256] = {};
  std::string* warnings = nullptr;
};

void read_bytes(png_structp png, png_bytep out, std::size_t n) {
  auto* src = static_cast<PngSource*>(png_get_io_ptr(png));
  if (n > src->bytes.size() - src->at) png_error(png, "the file ends inside the image data");
  std::memcpy(out, src->bytes.data() + src->at, n);
  src->at += n;
}

[[noreturn]] void on_error(png_structp png, png_const_charp message) {
  auto* src = static_cast<PngSource*>(png_get_error_ptr(png));
  std::snprintf(src->error, sizeof src->error, "%s", message);
  png_longjmp(png, 1);
}

void on_warning(png_structp png, png_const_charp message) {
  auto* src = static_cast<PngSource*>(png_get_error_ptr(png));
  if (!src->warnings->empty()) *src->warnings += "; ";
  *src->warnings += std::string("libpng warning: ") + message;  // as libpng's own handler says
}

// The read and info structs, destroyed whatever happens.
struct PngReader {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngReader() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

// Reads the header and sets OpenCV's IMREAD_COLOR transforms (grfmt_png.cpp's readData): 8-bit
// RGB out of any colour type and depth. False when libpng gave up (src.error says why).
bool read_header(PngReader& r, png_uint_32& width, png_uint_32& height) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_read_info(r.png, r.info);
  int depth = 0, colour = 0;
  png_get_IHDR(r.png, r.info, &width, &height, &depth, &colour, nullptr, nullptr, nullptr);
  if (depth == 16) png_set_strip_16(r.png);
  png_set_strip_alpha(r.png);
  if (colour == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(r.png);
  if ((colour & PNG_COLOR_MASK_COLOR) == 0 && depth < 8) png_set_expand_gray_1_2_4_to_8(r.png);
  if ((colour & PNG_COLOR_MASK_COLOR) == 0) png_set_gray_to_rgb(r.png);
  png_set_interlace_handling(r.png);
  png_read_update_info(r.png, r.info);
  return png_get_rowbytes(r.png, r.info) == 3 * static_cast<std::size_t>(width);
}

// Decodes every row into `rows` (allocated by the caller: nothing is allocated between setjmp
// and a longjmp).
bool read_rows(PngReader& r, std::vector<png_bytep>& rows) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_read_image(r.png, rows.data());
  png_read_end(r.png, nullptr);
  return true;
}

}  // namespace

RgbImage decode_png(std::string_view bytes, const std::string& name, std::string& warnings) {
  PngSource src{bytes, 0, {}, &warnings};
  PngReader r;
  r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &src, on_error, on_warning);
  if (r.png) r.info = png_create_info_struct(r.png);
  if (!r.png || !r.info) throw InputError(name, "PNG data", "libpng could not start (out of memory)");
  png_set_read_fn(r.png, &src, read_bytes);
  const auto fail = [&](const char* stage) {
    throw InputError(name, "PNG data",
                     std::string("cannot decode the image (") + stage + "; libpng: " +
                         (src.error[0] ? src.error : "unsupported layout") + ")");
  };
  png_uint_32 width = 0, height = 0;
  if (!read_header(r, width, height)) fail("header");
  std::vector<png_byte> pixels(3 * static_cast<std::size_t>(width) * height);
  std::vector<png_bytep> rows(height);
  for (png_uint_32 y = 0; y < height; ++y) rows[y] = pixels.data() + 3 * std::size_t{width} * y;
  if (!read_rows(r, rows)) fail("pixel data");
  RgbImage out(static_cast<int>(width), static_cast<int>(height));
  const png_byte* p = pixels.data();
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x, p += 3)
      out(x, y) = {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f};
  return out;
}

}  // namespace scantrace::grade
