#include "grade/image_precheck.hpp"

#include <spdlog/fmt/fmt.h>

#include "io/input_error.hpp"
#include "io/npy_reader.hpp"
#include "src/painter.hpp"

namespace scantrace::grade {

bool size_decides(std::int64_t width, std::int64_t height, int canvas_width, int canvas_height) {
  const bool canvas = width == canvas_width && height == canvas_height;
  const bool swapped = width == canvas_height && height == canvas_width;
  return !canvas && !swapped;
}

bool precheck_image(std::string_view bytes, const std::string& name, DeclaredSizeReader read_size,
                    int canvas_width, int canvas_height, ImageHeader& header) {
  if (is_npy(bytes)) {
    // The header only (its dtype, order and shape checked); no value is read.
    const NpyLayout npy = parse_npy_layout(bytes, name, kMaxNpyImageBytes);
    header = {"npy", npy.width, npy.height};
  } else if (!read_size(bytes, name, header.width, header.height, header.format)) {
    throw InputError(name, "", read_size == &declared_png_or_bmp_size
                                   ? "not a PNG, BMP or .npy file"
                                   : "not a PNG, JPEG, BMP or .npy file");
  }
  const std::string element = header.format == "npy" ? "npy header shape" : header.format + " header";
  check_pixel_limit(header.width, header.height, name, element);
  if (size_decides(header.width, header.height, canvas_width, canvas_height)) return true;
  check_before_decoding(bytes, name, header.width, header.height, header.format);
  return false;
}

DiffReport canvas_size_report(const Scene& scene, const FillOptions& options,
                              const ImageHeader& header, const DiffOptions& diff_options) {
  DiffReport r;
  r.width = scene.width, r.height = scene.height;
  r.image_width = static_cast<int>(header.width), r.image_height = static_cast<int>(header.height);
  r.tolerance = diff_options.tolerance;
  for (const char* c : kCategories) r.categories[c] = 0;
  // The words global_mistakes.cpp uses for a decoded image of another size.
  r.global.push_back({"canvas_size",
                      fmt::format("the image is {}x{}, the scene's canvas is {}x{}", header.width,
                                  header.height, scene.width, scene.height),
                      false});
  r.notes.push_back(fmt::format(
      "no pixel was compared: the {} header declares {}x{}, not the canvas's size, so the image "
      "was not decoded",
      header.format, header.width, header.height));
  r.category_map.assign(static_cast<std::size_t>(scene.width) * scene.height, 0);
  r.reference = render<Rgb32f>(scene, options);
  return r;
}

}  // namespace scantrace::grade
