#include "grade/image_input.hpp"

#include <spdlog/spdlog.h>

#include "grade/jpeg_header.hpp"
#include "grade/png_decoder.hpp"
#include "io/input_error.hpp"
#include "io/json_input.hpp"
#include "io/memory_budget.hpp"

namespace scantrace::grade {
bool declared_size(std::string_view b, const std::string& name, std::int64_t& width,
                   std::int64_t& height, std::string& format) {
  if (declared_png_or_bmp_size(b, name, width, height, format)) return true;
  if (b.size() >= 3 && static_cast<unsigned char>(b[0]) == 0xFF &&
      static_cast<unsigned char>(b[1]) == 0xD8) {
    format = "jpeg";
    const JpegHeader header = read_jpeg_header(b);
    if (!header.ok)
      throw InputError(name, "JPEG header", "cannot be read (libjpeg: " + header.problem + ")");
    width = header.width, height = header.height;
    return true;
  }
  return false;
}

SubmittedImage decode_image(std::string_view bytes, const std::string& name,
                            JpegBmpDecoder jpeg_bmp) {
  if (is_npy(bytes)) return decode_npy(bytes, name);
  SubmittedImage out;
  out.name = name;
  std::int64_t w = 0, h = 0;
  if (!declared_size(bytes, name, w, h, out.format))
    throw InputError(name, "", "not a PNG, JPEG, BMP or .npy file");
  check_before_decoding(bytes, name, w, h, out.format);
  if (out.format == "png") {  // libpng itself: no OpenCV (grade/png_decoder.hpp)
    std::string said;
    out.pixels = decode_png(bytes, name, said);
    if (!said.empty()) spdlog::warn("warning: {}: the png decoder said: {}", name, said);
  } else if (jpeg_bmp != nullptr) {
    jpeg_bmp(bytes, out);
  } else {
    throw InputError(name, "",
                     "a " + out.format + " image cannot be decoded here (PNG and .npy can)");
  }
  return out;
}

SubmittedImage read_submitted_image(const std::filesystem::path& file, JpegBmpDecoder jpeg_bmp) {
  return within_memory(file.string(), [&] {
    const std::string bytes = json_input::read_text_file(file);
    return decode_image(bytes, file.string(), jpeg_bmp);
  });
}

}  // namespace scantrace::grade
