// Reading scene files: JSON syntax, then the shape of every key (arrays of the right lengths,
// numbers where numbers belong), then the meaning (scantrace::validate: indices in range, colours
// in [0, 1], finite numbers, canvas size).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <istream>
#include <iterator>
#include <limits>
#include <optional>
#include <utility>

#include "io/json_input.hpp"
#include "io/memory_budget.hpp"
#include "io/pickled_scene.hpp"
#include "io/scene_json.hpp"
#include "io/scene_json_fast.hpp"

namespace scantrace {
namespace {

using nlohmann::json;

std::string at(const char* key, std::size_t i) {
  return std::string(key) + "[" + std::to_string(i) + "]";
}

std::optional<double> number(const json& v) {
  // Booleans are not numbers to nlohmann either, so `true` is refused rather than read as 1.
  if (!v.is_number()) return std::nullopt;
  return v.get<double>();
}

// An integer-valued number (3 or 3.0: files converted from numpy arrays often hold the latter).
// Values beyond 64 bits are returned as the nearest double's integer part, which callers treat
// as out of range like any other large value.
std::optional<long double> integer(const json& v) {
  if (v.is_number_unsigned()) return static_cast<long double>(v.get<std::uint64_t>());
  if (v.is_number_integer()) return static_cast<long double>(v.get<std::int64_t>());
  if (v.is_number_float()) {
    const double d = v.get<double>();
    if (std::isfinite(d) && d == std::floor(d)) return d;
  }
  return std::nullopt;
}

// Only finite components are clamped: a number too large for a double is damage, not a colour
// slightly out of range, and stays an error.
void clamp(Color& c, const std::string& element, ColorClamping& clamping) {
  bool changed = false;
  for (double* v : {&c.r, &c.g, &c.b})
    if (std::isfinite(*v) && (*v < 0.0 || *v > 1.0)) {
      *v = std::clamp(*v, 0.0, 1.0);
      changed = true;
    }
  if (!changed) return;
  if (clamping.clamped++ == 0) clamping.first = element;
}

// What follows reading the values, on either path: --clamp-colors, then the meaning
// (scantrace::validate).
void finish_scene(Scene& s, const std::string& file, ColorClamping* clamping) {
  if (clamping) {
    for (std::size_t i = 0; i < s.vcolors.size(); ++i)
      clamp(s.vcolors[i], at("vcolors", i), *clamping);
    clamp(s.background, "background", *clamping);
  }
  if (const auto problem = validate(s)) throw InputError(file, problem->element, problem->problem);
}

class SceneReader {
 public:
  SceneReader(const json& root, const std::string& file, ColorClamping* clamping)
      : root_(root), file_(file), clamping_(clamping) {}

  Scene read() {
    if (!root_.is_object())
      fail("", "expected a JSON object with the keys vertices, vcolors, faces and depth, got " +
                   json_input::quote(root_));
    Scene s;
    // All four arrays are required; check their presence first so that a file missing one
    // key is reported as such rather than by the first element problem of another key.
    const json& vertices = require("vertices");
    const json& vcolors = require("vcolors");
    const json& faces = require("faces");
    const json& depth = require("depth");

    read_array(vertices, "vertices", "[x, y] pairs", s.vertices, [&](const json& v, std::size_t i) {
      const auto xy = numbers<2>(v);
      if (!xy) fail(at("vertices", i), "expected [x, y] (2 numbers), got " + json_input::quote(v));
      return Vec2{(*xy)[0], (*xy)[1]};
    });
    read_array(vcolors, "vcolors", "[r, g, b] colours", s.vcolors,
               [&](const json& v, std::size_t i) { return color(v, at("vcolors", i)); });
    const std::size_t n = s.vertices.size();
    read_array(faces, "faces", "[i, j, k] vertex index triples", s.faces,
               [&](const json& v, std::size_t i) { return face(v, i, n); });
    read_array(depth, "depth", "numbers", s.depth, [&](const json& v, std::size_t i) {
      const auto d = number(v);
      if (!d) fail(at("depth", i), "expected a number, got " + json_input::quote(v));
      return *d;
    });

    if (const json* w = optional_key("width")) s.width = canvas_size(*w, "width");
    if (const json* h = optional_key("height")) s.height = canvas_size(*h, "height");
    if (const json* b = optional_key("background")) s.background = color(*b, "background");
    finish_scene(s, file_, clamping_);
    return s;
  }

 private:
  [[noreturn]] void fail(const std::string& element, const std::string& problem) const {
    throw InputError(file_, element, problem);
  }

  const json& require(const char* key) const {
    const auto it = root_.find(key);
    if (it == root_.end()) fail("", std::string("missing key \"") + key + "\"");
    return *it;
  }

  const json* optional_key(const char* key) const {
    const auto it = root_.find(key);
    return it == root_.end() ? nullptr : &*it;
  }

  template <class T, class ReadElement>
  void read_array(const json& array, const char* key, const char* what, std::vector<T>& out,
                  ReadElement read_element) const {
    if (!array.is_array())
      fail(key, std::string("expected an array of ") + what + ", got " + json_input::quote(array));
    out.reserve(array.size());
    std::size_t i = 0;
    for (const json& element : array) out.push_back(read_element(element, i++));
  }

  template <std::size_t N>
  static std::optional<std::array<double, N>> numbers(const json& v) {
    if (!v.is_array() || v.size() != N) return std::nullopt;
    std::array<double, N> out{};
    for (std::size_t k = 0; k < N; ++k) {
      const auto d = number(v[k]);
      if (!d) return std::nullopt;
      out[k] = *d;
    }
    return out;
  }

  Color color(const json& v, const std::string& element) const {
    const auto rgb = numbers<3>(v);
    if (!rgb) fail(element, "expected [r, g, b] (3 numbers), got " + json_input::quote(v));
    return {(*rgb)[0], (*rgb)[1], (*rgb)[2]};
  }

  std::array<int, 3> face(const json& v, std::size_t i, std::size_t vertex_count) const {
    if (!v.is_array() || v.size() != 3)
      fail(at("faces", i), "expected [i, j, k] (3 vertex indices), got " + json_input::quote(v));
    std::array<int, 3> out{};
    for (std::size_t k = 0; k < 3; ++k) {
      const auto index = integer(v[k]);
      if (!index)
        fail(at("faces", i), "vertex index " + json_input::quote(v[k]) + " is not an integer");
      // Indices that do not even fit an int are out of range; validate() reports the others
      // with the same wording.
      if (*index < 0 || *index >= static_cast<long double>(vertex_count))
        fail(at("faces", i), "vertex index " + json_input::quote(v[k]) + " is out of range (" +
                                 std::to_string(vertex_count) + " vertices)");
      out[k] = static_cast<int>(*index);
    }
    return out;
  }

  int canvas_size(const json& v, const char* key) const {
    const auto size = integer(v);
    if (!size) fail(key, "expected an integer number of pixels, got " + json_input::quote(v));
    if (*size < 1) fail(key, "canvas size must be positive, got " + json_input::quote(v));
    // Sizes that fit an int but are too large are left to validate() (the pixel-count limit).
    if (*size > std::numeric_limits<int>::max())
      fail(key, "canvas size " + json_input::quote(v) + " is too large");
    return static_cast<int>(*size);
  }

  const json& root_;
  const std::string& file_;
  ColorClamping* clamping_;
};

}  // namespace

namespace {

// Constant-initialized, so that a registration during static initialization is never undone.
constinit FastSceneReader fast_reader = nullptr;

// `padding`: bytes after the text that may be read (read_scene_fast).
Scene parse(std::string_view text, std::size_t padding, const std::string& name_for_errors,
            ColorClamping* clamping) {
  if (std::optional<Scene> s = fast_reader ? fast_reader(text, padding) : std::nullopt) {
    finish_scene(*s, name_for_errors, clamping);
    return std::move(*s);
  }
  return parse_scene_text_without_fast_path(text, name_for_errors, clamping);
}

}  // namespace

void register_fast_scene_reader(FastSceneReader reader) { fast_reader = reader; }

Scene parse_scene_text(std::string_view text, const std::string& name_for_errors,
                       ColorClamping* clamping) {
  return parse(text, 0, name_for_errors, clamping);
}

Scene parse_scene_text_without_fast_path(std::string_view text, const std::string& name_for_errors,
                                         ColorClamping* clamping) {
  const json root = json_input::parse(text, name_for_errors);
  return SceneReader(root, name_for_errors, clamping).read();
}

Scene parse_scene(std::istream& in, const std::string& name_for_errors, ColorClamping* clamping) {
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError(name_for_errors, "", "cannot read the input stream");
  return parse_scene_text(text, name_for_errors, clamping);
}

Scene load_scene(const std::filesystem::path& file, ColorClamping* clamping) {
  return within_memory(file.string(), [&] {
    const std::string text = json_input::read_text_file(file);
    // The course's hw1.npy (a pickled dict of arrays): the same scene in another container.
    if (looks_pickled(text) || file.extension() == ".npy") {
      Scene s = parse_pickled_scene(text, file.string());
      finish_scene(s, file.string(), clamping);
      return s;
    }
    return parse(text, text.capacity() - text.size(), file.string(), clamping);
  });
}

}  // namespace scantrace
