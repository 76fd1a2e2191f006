// The module's plumbing and render (bindings.hpp): what scantrace.mjs calls.
#include "web/bindings.hpp"

#include <emscripten/emscripten.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>

#include "io/input_error.hpp"
#include "io/obj_loader.hpp"
#include "io/scene_json.hpp"
#include "src/image.hpp"
#include "src/option_table.hpp"
#include "src/painter.hpp"
#include "src/shade_mesh.hpp"
#include "src/tracer.hpp"
#include "web/call_status.hpp"

namespace scantrace::web {

Result& result() {
  static Result r;
  return r;
}

int run(const std::function<void()>& work) {
  Result& r = result();
  r = Result{};
  return call_status(
      [&] {
        try {
          work();
        } catch (const nlohmann::json::exception& e) {
          // An option of the wrong type read with nlohmann's value(): a bad argument, said
          // without the library's "[json.exception.type_error.302]".
          const std::string what = e.what();
          const std::size_t end = what.find("] ");
          throw std::invalid_argument("options: a value of the wrong type (" +
                                      (end == std::string::npos ? what : what.substr(end + 2)) + ")");
        }
      },
      r.error);
}

int pixel_coordinate(double v, char axis) {
  // The command reads X and Y with from_chars into an int: an integer, 0 or more, that fits.
  if (!(v >= 0 && v <= 2147483647.0 && std::floor(v) == v))
    throw std::invalid_argument(std::string(1, axis) + ": must be a pixel " +
                                (axis == 'X' ? "column, 0 to the canvas width" : "row, 0 to the canvas height") +
                                " - 1 (got \"" + fmt::format("{}", v) + "\")");
  return static_cast<int>(v);
}

double tolerance_option(const nlohmann::json& o) {
  if (!o.contains("tolerance")) return 1.0 / 255.0;
  const nlohmann::json& t = o["tolerance"];
  // (JSON has no NaN: JSON.stringify writes NaN and the infinities as null.)
  if (!t.is_number() || !std::isfinite(t.get<double>()))
    throw std::invalid_argument("tolerance: \"" + t.dump() + "\" is not a finite number");
  const double v = t.get<double>();
  // --tolerance's check, CLI::Range(0.0, 1.0), and its words.
  if (!(v >= 0 && v <= 1))
    throw std::invalid_argument("tolerance: Value " + fmt::format("{}", v) +
                                " not in range 0.000000 to 1.000000");
  return v;
}

bool same_bytes(const void* a, const void* b, std::size_t n) {
  const auto* p = static_cast<const unsigned char*>(a);
  const auto* q = static_cast<const unsigned char*>(b);
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    std::uint64_t x, y;
    std::memcpy(&x, p + i, 8);
    std::memcpy(&y, q + i, 8);
    if (x != y) return false;
  }
  for (; i < n; ++i)
    if (p[i] != q[i]) return false;
  return true;
}

void put_rgba(const RgbImage& image, std::vector<std::uint8_t>& bytes) {
  const std::size_t w = static_cast<std::size_t>(image.width());
  bytes.resize(w * static_cast<std::size_t>(image.height()) * 4);
  std::uint8_t* out = bytes.data();
  // A pixel equal to the one before it takes that one's bytes, and a row equal to the one above
  // takes its row of bytes: most of a triangle's canvas is its background (above and below the
  // triangle, whole rows of it), and this conversion was a seventh of the module's time in a
  // drag's mouse move in the explorer (docs/performance.md).
  Rgb32f last{};
  std::uint8_t last_bytes[4] = {to_byte(last.r), to_byte(last.g), to_byte(last.b), 255};
  for (int y = 0; y < image.height(); ++y) {
    const Rgb32f* row = image.row(y);
    if (y > 0 && same_bytes(row, image.row(y - 1), w * sizeof(Rgb32f))) {
      std::memcpy(out, out - w * 4, w * 4);
      out += w * 4;
      continue;
    }
    for (int x = 0; x < image.width(); ++x, out += 4) {
      const Rgb32f& p = row[x];
      if (!(p.r == last.r && p.g == last.g && p.b == last.b)) {
        last = p;
        last_bytes[0] = to_byte(p.r);
        last_bytes[1] = to_byte(p.g);
        last_bytes[2] = to_byte(p.b);
      }
      std::memcpy(out, last_bytes, 4);
    }
  }
}

nlohmann::json parse_options(const char* text) {
  if (!text || !*text) return nlohmann::json::object();
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object()) throw std::invalid_argument("options: not a JSON object");
  return j;
}

namespace {

std::string text_option(const nlohmann::json& o, const char* key, const char* fallback) {
  if (!o.contains(key)) return fallback;
  if (!o[key].is_string()) throw std::invalid_argument(std::string("options.") + key + ": not a string");
  return o[key].get<std::string>();
}

[[noreturn]] void unknown(const char* key, const std::string& value) {
  throw std::invalid_argument(std::string("options.") + key + ": unknown value \"" + value + "\"");
}

// options[key]: a name of E's table (src/option_table.hpp), or `fallback` when absent.
template <class E>
E named_option(const nlohmann::json& o, const char* key, E fallback) {
  const std::string name = text_option(o, key, option_name(fallback));
  const std::optional<E> e = parse_option<E>(name);
  if (!e) unknown(key, name);
  return *e;
}

int subpixel_bits_option(const nlohmann::json& o) {
  if (!o.contains("subpixel_bits")) return FillOptions{}.subpixel_bits;
  if (!o["subpixel_bits"].is_number_integer() || o["subpixel_bits"].get<int>() < 0 ||
      o["subpixel_bits"].get<int>() > kMaxSubpixelBits)
    throw std::invalid_argument("options.subpixel_bits: an integer 0 to " +
                                std::to_string(kMaxSubpixelBits));
  return o["subpixel_bits"].get<int>();
}

template <class E>
void add_table(nlohmann::json& out) {
  const OptionTable<E>& t = option_table<E>();
  out[t.key] = {{"names", t.names()}, {"default", t.default_name()}};
}

}  // namespace

FillOptions fill_options(const nlohmann::json& o, bool model) {
  FillOptions f;
  f.shading = named_option(o, "shading", f.shading);
  f.fill_rule = named_option(o, "fill_rule", f.fill_rule);
  f.subpixel_bits = subpixel_bits_option(o);
  f.method = named_option(o, "method", f.method);
  f.winding_rule = named_option(o, "winding", f.winding_rule);
  // A model is culled back faces by default and a scene not, as `render` does (cli/model_flags).
  f.cull = named_option(o, "cull", model ? Cull::back : f.cull);
  f.visibility = named_option(o, "depth", f.visibility);
  return f;
}

Scene load_scene(const std::string& path, const nlohmann::json& options) {
  if (is_obj_file(path)) {
    ShadeOptions o;
    o.shading = fill_options(options, true).shading;
    return shade_mesh(load_obj(path), o);
  }
  const bool clamp = options.value("clamp_colors", false);
  ColorClamping clamping;
  try {
    return scantrace::load_scene(path, clamp ? &clamping : nullptr);
  } catch (const InputError& e) {
    // The CLI's hint for the one problem an option fixes (cli/scene_input.cpp).
    if (clamp || e.problem().find("outside [0, 1]") == std::string::npos) throw;
    throw InputError(e.file(), e.element(), e.problem() + " (--clamp-colors clamps it)");
  }
}

}  // namespace scantrace::web

using namespace scantrace;

extern "C" {

EMSCRIPTEN_KEEPALIVE const char* st_result_text() { return web::result().text.c_str(); }
EMSCRIPTEN_KEEPALIVE std::size_t st_result_size() { return web::result().text.size(); }
EMSCRIPTEN_KEEPALIVE const std::uint8_t* st_result_bytes() { return web::result().bytes_out().data(); }
EMSCRIPTEN_KEEPALIVE std::size_t st_result_bytes_size() { return web::result().bytes_out().size(); }
EMSCRIPTEN_KEEPALIVE const char* st_error() { return web::result().error.c_str(); }
EMSCRIPTEN_KEEPALIVE const char* st_warning() { return web::result().warning.c_str(); }

// Every option table of src/option_table.hpp as JSON, by the table's key (as a trace header and
// Python's option_names() key them): {"method": {"names": ["exact", ...], "default": "exact"},
// ...}, so a page takes its choices and defaults from the tables the module parses them with.
EMSCRIPTEN_KEEPALIVE const char* st_option_table() {
  static const std::string text = [] {
    nlohmann::json j = nlohmann::json::object();
    web::add_table<Shading>(j);
    web::add_table<FillRule>(j);
    web::add_table<Method>(j);
    web::add_table<WindingRule>(j);
    web::add_table<Cull>(j);
    web::add_table<Visibility>(j);
    web::add_table<Occlusion>(j);
    web::add_table<TraceLevel>(j);
    return j.dump();
  }();
  return text.c_str();
}

// The scene file at `path` rendered as `scantrace render` renders it (one thread): the result's
// bytes are RGBA, 8 bits a channel, converted by to_byte as the PNG writer converts; its text
// {"width", "height", "faces", "ms"}.
EMSCRIPTEN_KEEPALIVE int st_render(const char* path, const char* options_json) {
  return web::run([&] {
    const nlohmann::json o = web::parse_options(options_json);
    const Scene scene = web::load_scene(path, o);
    const FillOptions options = web::fill_options(o, is_obj_file(path));
    const double t0 = emscripten_get_now();
    const RgbImage image = render(scene, options);
    const double ms = emscripten_get_now() - t0;
    web::put_rgba(image, web::result().bytes);
    web::result().text = nlohmann::json{{"width", image.width()},
                                        {"height", image.height()},
                                        {"faces", scene.faces.size()},
                                        {"ms", ms}}
                             .dump();
  });
}

}  // extern "C"
