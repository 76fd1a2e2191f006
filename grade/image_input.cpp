#include "grade/image_input.hpp"

#include <spdlog/spdlog.h>

#include "grade/diff_report.hpp"
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

std::optional<SubmittedImage> read_submitted_image(const std::filesystem::path& file,
                                                   JpegBmpDecoder jpeg_bmp, int canvas_width,
                                                   int canvas_height, ImageHeader& header) {
  return within_memory(file.string(), [&]() -> std::optional<SubmittedImage> {
    const std::string bytes = json_input::read_text_file(file);
    if (precheck_image(bytes, file.string(), &declared_size, canvas_width, canvas_height, header))
      return std::nullopt;
    return decode_image(bytes, file.string(), jpeg_bmp);
  });
}

DiffReport diff_image_file(const Scene& scene, const FillOptions& options,
                           const std::filesystem::path& file, JpegBmpDecoder jpeg_bmp,
                           const DiffOptions& diff_options) {
  ImageHeader header;
  const std::optional<SubmittedImage> image =
      read_submitted_image(file, jpeg_bmp, scene.width, scene.height, header);
  if (!image) return canvas_size_report(scene, options, header, diff_options);
  return diff(scene, options, *image, diff_options);
}

}  // namespace scantrace::grade
