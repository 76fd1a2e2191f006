// why and diff (bindings.hpp): the JSON `scantrace why --json` and `scantrace diff --json` print.
#include <emscripten/emscripten.h>

#include <string>

#include "grade/diff_picture.hpp"
#include "grade/diff_report.hpp"
#include "grade/image_input.hpp"
#include "grade/pixel_story.hpp"
#include "grade/scene_around.hpp"
#include "io/input_error.hpp"
#include "io/obj_loader.hpp"
#include "web/bindings.hpp"

using namespace scantrace;

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
    const Scene scene = web::load_scene(path, o);
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
    grade::DiffOptions d;
    d.tolerance = o.value("tolerance", 1.0 / 255.0);
    d.undo = o.value("undo", true);
    const grade::DiffReport report =
        grade::diff(scene, web::fill_options(o, is_obj_file(path)), image, d);
    web::result().text = report.to_json().dump(2) + "\n";
    // The picture of the differences (grade/diff_picture.hpp), RGB to RGBA for a canvas.
    const std::vector<std::uint8_t> rgb = grade::diff_picture(report);
    auto& bytes = web::result().bytes;
    bytes.resize(rgb.size() / 3 * 4);
    for (std::size_t i = 0, j = 0; i < rgb.size(); i += 3, j += 4) {
      bytes[j] = rgb[i];
      bytes[j + 1] = rgb[i + 1];
      bytes[j + 2] = rgb[i + 2];
      bytes[j + 3] = 255;
    }
  });
}

}  // extern "C"
