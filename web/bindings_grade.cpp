// why and diff (bindings.hpp): the JSON `scantrace why --json` and `scantrace diff --json` print.
#include <emscripten/emscripten.h>

#include <fstream>
#include <sstream>
#include <string>

#include "grade/diff_picture.hpp"
#include "grade/diff_report.hpp"
#include "grade/image_header.hpp"
#include "grade/pixel_story.hpp"
#include "grade/scene_around.hpp"
#include "io/input_error.hpp"
#include "io/obj_loader.hpp"
#include "web/bindings.hpp"

using namespace scantrace;

namespace {

std::string file_bytes(const char* path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(std::string(path) + ": no such file in the module");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// `scantrace diff --json`'s report of `image` against the scene at `path`, in the result's text;
// the picture of the differences (grade/diff_picture.hpp), RGBA at the scene's canvas size, in
// its bytes.
void diff_into_result(const char* path, const grade::SubmittedImage& image,
                      const nlohmann::json& o) {
  const Scene scene = web::load_scene(path, o);
  grade::DiffOptions d;
  d.tolerance = o.value("tolerance", 1.0 / 255.0);
  d.undo = o.value("undo", true);
  const grade::DiffReport report =
      grade::diff(scene, web::fill_options(o, is_obj_file(path)), image, d);
  web::result().text = report.to_json().dump(2) + "\n";
  const std::vector<std::uint8_t> rgb = grade::diff_picture(report);
  auto& bytes = web::result().bytes;
  bytes.resize(rgb.size() / 3 * 4);
  for (std::size_t i = 0, j = 0; i < rgb.size(); i += 3, j += 4) {
    bytes[j] = rgb[i];
    bytes[j + 1] = rgb[i + 1];
    bytes[j + 2] = rgb[i + 2];
    bytes[j + 3] = 255;
  }
}

}  // namespace

extern "C" {

// Why pixel (x, y) of the scene file at `path` has its colour: `scantrace why --json`'s document.
EMSCRIPTEN_KEEPALIVE int st_why(const char* path, int x, int y, const char* options_json) {
  return web::run([&] {
    const nlohmann::json o = web::parse_options(options_json);
    const Scene scene = web::load_scene(path, o);
    if (x < 0 || y < 0 || x >= scene.width || y >= scene.height)
      throw InputError(path, "X Y",
                       "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                           ") is outside the " + std::to_string(scene.width) + "x" +
                           std::to_string(scene.height) + " canvas");
    const grade::PixelStory story =
        grade::why(scene, web::fill_options(o, is_obj_file(path)), x, y);
    web::result().text = story.to_json().dump(2) + "\n";
  });
}

// The submitted image (`width` × `height` RGBA bytes, decoded by the caller from the file `name`)
// compared with the scene's reference render: `scantrace diff --json`'s report. options:
// the fill options, "tolerance" (1/255), "undo" (true), "format" ("png"). The result's bytes:
// the picture of the differences, RGBA, at the scene's canvas size.
EMSCRIPTEN_KEEPALIVE int st_diff(const char* path, const std::uint8_t* rgba, int width, int height,
                                 const char* name, const char* options_json) {
  return web::run([&] {
    const nlohmann::json o = web::parse_options(options_json);
    grade::SubmittedImage image;
    image.pixels = RgbImage(width, height);
    for (int yy = 0; yy < height; ++yy)
      for (int xx = 0; xx < width; ++xx) {
        const std::uint8_t* p = rgba + (static_cast<std::size_t>(yy) * width + xx) * 4;
        // As grade/image_input.cpp converts a decoded file: bytes / 255 in float.
        image.pixels(xx, yy) = {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f};
      }
    image.format = o.value("format", std::string("png"));
    image.eight_bit = true;
    image.name = name;
    diff_into_result(path, image, o);
  });
}

// The image file at `image_path` (the module's file system) as `scantrace diff` reads it before
// any decoder runs (grade/image_header.hpp): a PNG's or BMP's header checked, {"format", "width",
// "height"} in the result's text (the page then decodes it with the browser's decoder), or a .npy
// decoded ("format": "npy"). Bad input: the command's line (status 1).
EMSCRIPTEN_KEEPALIVE int st_image_header(const char* image_path) {
  return web::run([&] {
    const std::string bytes = file_bytes(image_path);
    std::int64_t w = 0, h = 0;
    std::string format = "npy";
    if (grade::is_npy(bytes)) {
      const grade::SubmittedImage npy = grade::decode_npy(bytes, image_path);
      w = npy.pixels.width(), h = npy.pixels.height();
    } else {
      if (!grade::declared_png_or_bmp_size(bytes, image_path, w, h, format))
        throw InputError(image_path, "", "not a PNG, BMP or .npy file (the page reads these)");
      grade::check_before_decoding(bytes, image_path, w, h, format);
    }
    web::result().text = nlohmann::json{{"format", format}, {"width", w}, {"height", h}}.dump();
  });
}

// The .npy file at `image_path` compared with the scene at `path`, as `scantrace diff SCENE
// IMAGE.npy --json` compares them (the array decoded by grade/image_header.hpp; a float array is
// not 8-bit). The result as st_diff's.
EMSCRIPTEN_KEEPALIVE int st_diff_npy(const char* path, const char* image_path,
                                     const char* options_json) {
  return web::run([&] {
    const nlohmann::json o = web::parse_options(options_json);
    const std::string bytes = file_bytes(image_path);
    if (!grade::is_npy(bytes)) throw std::invalid_argument("diff: the file is not a .npy array");
    diff_into_result(path, grade::decode_npy(bytes, image_path), o);
  });
}

}  // extern "C"
