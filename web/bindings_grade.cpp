// why and diff (bindings.hpp): the JSON `scantrace why --json` and `scantrace diff --json` print.
#include <emscripten/emscripten.h>

#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "grade/diff_picture.hpp"
#include "grade/diff_report.hpp"
#include "grade/image_header.hpp"
#include "grade/image_precheck.hpp"
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

// `report` as `scantrace diff --json` prints it, in the result's text; the picture of the
// differences (grade/diff_picture.hpp), RGBA at the scene's canvas size, in its bytes.
void report_into_result(const grade::DiffReport& report) {
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

grade::DiffOptions diff_options(const nlohmann::json& o) {
  grade::DiffOptions d;
  d.tolerance = web::tolerance_option(o);
  d.undo = o.value("undo", true);
  return d;
}

// The image file at `image_path` against the scene at `path` (the options' fill options), through
// the command's pre-check (grade/image_precheck.hpp): the report when the header decides (a
// size other than the canvas's: nothing decoded), else nullopt and `header` says what it holds.
std::optional<grade::DiffReport> precheck_against_scene(const char* path, const Scene& scene,
                                                        const std::string& bytes,
                                                        const char* image_path,
                                                        const nlohmann::json& o,
                                                        grade::ImageHeader& header) {
  if (!grade::precheck_image(bytes, image_path, &grade::declared_png_or_bmp_size, scene.width,
                             scene.height, header))
    return std::nullopt;
  return grade::canvas_size_report(scene, web::fill_options(o, is_obj_file(path)), header,
                                   diff_options(o));
}

}  // namespace

extern "C" {

// Why pixel (x, y) of the scene file at `path` has its colour: `scantrace why --json`'s document,
// and as the result's bytes the command's text of the same story (PixelStory::to_text, UTF-8),
// so a page shows the command's words without writing them again.
// x and y come as doubles, so nothing is truncated on the way: 2^32 + 100, NaN or 100.9 are the
// command's usage error, a pixel off the canvas its bad input.
EMSCRIPTEN_KEEPALIVE int st_why(const char* path, double x_in, double y_in, const char* options_json) {
  return web::run([&] {
    const int x = web::pixel_coordinate(x_in, 'X'), y = web::pixel_coordinate(y_in, 'Y');
    const nlohmann::json o = web::parse_options(options_json);
    const Scene scene = web::load_scene(path, o);
    if (x >= scene.width || y >= scene.height)
      throw InputError(path, "X Y",
                       "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                           ") is outside the " + std::to_string(scene.width) + "x" +
                           std::to_string(scene.height) + " canvas");
    const grade::PixelStory story =
        grade::why(scene, web::fill_options(o, is_obj_file(path)), x, y);
    web::result().text = story.to_json().dump(2) + "\n";
    const std::string prose = story.to_text();
    web::result().bytes.assign(prose.begin(), prose.end());
  });
}

// The submitted image (`width` × `height` RGBA bytes, decoded by the caller from the file `name`)
// compared with the scene's reference render: `scantrace diff --json`'s report. options:
// the fill options, "tolerance" (1/255), "undo" (true), "format" ("png"). The result's bytes:
// the picture of the differences, RGBA, at the scene's canvas size. A size other than the
// canvas's is the report the command gives of the file from its header (canvas_size, no pixel
// compared: grade/image_precheck.hpp), so the page's report is the command's.
EMSCRIPTEN_KEEPALIVE int st_diff(const char* path, const std::uint8_t* rgba, int width, int height,
                                 const char* name, const char* options_json) {
  return web::run([&] {
    const nlohmann::json o = web::parse_options(options_json);
    const grade::DiffOptions d = diff_options(o);
    const Scene scene = web::load_scene(path, o);
    const FillOptions fill = web::fill_options(o, is_obj_file(path));
    const std::string format = o.value("format", std::string("png"));
    grade::check_pixel_limit(width, height, name, format + " image");
    if (grade::size_decides(width, height, scene.width, scene.height))
      return report_into_result(grade::canvas_size_report(scene, fill, {format, width, height}, d));
    grade::SubmittedImage image;
    image.pixels = RgbImage(width, height);
    for (int yy = 0; yy < height; ++yy)
      for (int xx = 0; xx < width; ++xx) {
        const std::uint8_t* p = rgba + (static_cast<std::size_t>(yy) * width + xx) * 4;
        // As grade/image_input.cpp converts a decoded file: bytes / 255 in float.
        image.pixels(xx, yy) = {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f};
      }
    image.format = format;
    image.eight_bit = true;
    image.name = name;
    report_into_result(grade::diff(scene, fill, image, d));
  });
}

// The image file at `image_path` (the module's file system) as `scantrace diff` reads it before
// any decoder runs: {"format", "width", "height"} in the result's text (the page then decodes it
// with the browser's decoder), a .npy decoded ("format": "npy"). With a scene (`path` not empty),
// the command's pre-check against its canvas (grade/image_precheck.hpp): a size other than the
// canvas's adds "report", the diff report made from the header alone (its picture in the
// result's bytes), and nothing is decoded. Bad input: the command's line (status 1).
EMSCRIPTEN_KEEPALIVE int st_image_header(const char* image_path, const char* path,
                                         const char* options_json) {
  return web::run([&] {
    const nlohmann::json o = web::parse_options(options_json);
    const std::string bytes = file_bytes(image_path);
    grade::ImageHeader header;
    std::optional<grade::DiffReport> report;
    if (*path) {
      report = precheck_against_scene(path, web::load_scene(path, o), bytes, image_path, o, header);
    } else if (!grade::is_npy(bytes)) {
      if (!grade::declared_png_or_bmp_size(bytes, image_path, header.width, header.height,
                                           header.format))
        throw InputError(image_path, "", "not a PNG, BMP or .npy file (the page reads these)");
      grade::check_before_decoding(bytes, image_path, header.width, header.height, header.format);
    }
    if (!report && grade::is_npy(bytes)) {  // its values checked too
      const grade::SubmittedImage npy = grade::decode_npy(bytes, image_path);
      header = {"npy", npy.pixels.width(), npy.pixels.height()};
    }
    nlohmann::json j{{"format", header.format}, {"width", header.width}, {"height", header.height}};
    if (report) {
      report_into_result(*report);
      j["report"] = nlohmann::json::parse(web::result().text);
    }
    web::result().text = j.dump();
  });
}

// The .npy file at `image_path` compared with the scene at `path`, as `scantrace diff SCENE
// IMAGE.npy --json` compares them (the pre-check against the canvas first, then the array decoded
// by grade/image_header.hpp; a float array is not 8-bit). The result as st_diff's.
EMSCRIPTEN_KEEPALIVE int st_diff_npy(const char* path, const char* image_path,
                                     const char* options_json) {
  return web::run([&] {
    const nlohmann::json o = web::parse_options(options_json);
    const std::string bytes = file_bytes(image_path);
    if (!grade::is_npy(bytes)) throw std::invalid_argument("diff: the file is not a .npy array");
    const Scene scene = web::load_scene(path, o);
    grade::ImageHeader header;
    if (auto report = precheck_against_scene(path, scene, bytes, image_path, o, header))
      return report_into_result(*report);
    report_into_result(grade::diff(scene, web::fill_options(o, is_obj_file(path)),
                                   grade::decode_npy(bytes, image_path), diff_options(o)));
  });
}

}  // extern "C"
