#include "io/scene_json_fast.hpp"

#include <simdjson.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>

#include "io/memory_budget.hpp"

namespace scantrace {
namespace {

using simdjson::dom::array;
using simdjson::dom::element;
using simdjson::dom::element_type;
using simdjson::dom::object;

// A number as nlohmann's get<double>() gives it: integers converted, booleans refused.
bool number(element e, double& out) {
  switch (e.type()) {
    case element_type::DOUBLE:
      out = e.get_double().value_unsafe();
      return true;
    case element_type::INT64:
      out = static_cast<double>(e.get_int64().value_unsafe());
      return true;
    case element_type::UINT64:
      out = static_cast<double>(e.get_uint64().value_unsafe());
      return true;
    default:
      return false;
  }
}

template <std::size_t N>
bool numbers(element e, std::array<double, N>& out) {
  array a;
  if (e.get_array().get(a) || a.size() != N) return false;
  std::size_t k = 0;
  for (element v : a)
    if (!number(v, out[k++])) return false;
  return true;
}

// An integer written as one (3, not 3.0: the nlohmann reader accepts that and says nothing of it,
// so the fast path leaves it to that reader) in [lo, hi].
bool integer(element e, std::int64_t lo, std::int64_t hi, std::int64_t& out) {
  return e.type() == element_type::INT64 && !e.get_int64().get(out) && out >= lo && out <= hi;
}

template <class T, class Read>
bool read_array(element e, std::vector<T>& out, Read read) {
  array a;
  if (e.get_array().get(a)) return false;
  out.resize(a.size());
  std::size_t i = 0;
  for (element v : a)
    if (!read(v, out[i++])) return false;
  return true;
}

// The keys both readers read, in this order (the first four are required).
constexpr std::string_view kKeys[] = {"vertices", "vcolors", "faces",     "depth",
                                      "width",    "height",  "background"};

// The scene by simdjson's DOM: what read_on_demand declines (a key the scene does not
// use, whose value that reader would not look at) is read here, every value checked.
std::optional<Scene> read_dom(simdjson::padded_string_view text) {
  simdjson::dom::parser parser;
  element root;
  object fields;
  if (parser.parse(text.data(), text.size(), false).get(root) || root.get_object().get(fields))
    return std::nullopt;
  // Each key given once (nlohmann and simdjson differ on which of two wins).
  std::array<std::optional<element>, std::size(kKeys)> value;
  for (const auto field : fields)
    for (std::size_t k = 0; k < std::size(kKeys); ++k)
      if (field.key == kKeys[k]) {
        if (value[k]) return std::nullopt;
        value[k] = field.value;
      }
  if (!value[0] || !value[1] || !value[2] || !value[3]) return std::nullopt;

  Scene s;
  std::array<double, 2> xy;
  std::array<double, 3> rgb;
  if (!read_array(*value[0], s.vertices,
                  [&](element e, Vec2& v) {
                    return numbers(e, xy) && (v = Vec2{xy[0], xy[1]}, true);
                  }) ||
      !read_array(*value[1], s.vcolors, [&](element e, Color& c) {
        return numbers(e, rgb) && (c = Color{rgb[0], rgb[1], rgb[2]}, true);
      }))
    return std::nullopt;
  const auto last_vertex = static_cast<std::int64_t>(s.vertices.size()) - 1;
  if (!read_array(*value[2], s.faces,
                  [&](element e, std::array<int, 3>& f) {
                    array a;
                    if (e.get_array().get(a) || a.size() != 3) return false;
                    std::size_t k = 0;
                    for (element i : a) {
                      std::int64_t index;
                      if (!integer(i, 0, last_vertex, index)) return false;
                      f[k++] = static_cast<int>(index);
                    }
                    return true;
                  }) ||
      !read_array(*value[3], s.depth, [](element e, double& d) { return number(e, d); }))
    return std::nullopt;
  std::int64_t size;
  constexpr std::int64_t kMaxInt = std::numeric_limits<int>::max();
  if (value[4]) {
    if (!integer(*value[4], 1, kMaxInt, size)) return std::nullopt;
    s.width = static_cast<int>(size);
  }
  if (value[5]) {
    if (!integer(*value[5], 1, kMaxInt, size)) return std::nullopt;
    s.height = static_cast<int>(size);
  }
  if (value[6]) {
    if (!numbers(*value[6], rgb)) return std::nullopt;
    s.background = Color{rgb[0], rgb[1], rgb[2]};
  }
  return s;
}

// The same reading by simdjson's On-Demand front end, which parses each number where the reader
// asks for it instead of first writing every value to a tape: the 1200² bench scene (10.5 MB,
// 527 k numbers) in 14 ms against 26 (docs/performance.md). On-Demand checks only what it is
// asked to read, so this reader reads every value of the document or declines: a key the scene
// does not use (whose value On-Demand would skip unchecked) is left to read_dom.
namespace od = simdjson::ondemand;

// A number as nlohmann's get<double>() gives it, as number() above: an integer (-0 included)
// converted from its integer value.
bool number(od::value v, double& out) {
  od::number_type type;
  if (v.get_number_type().get(type)) return false;
  if (type == od::number_type::signed_integer) {
    std::int64_t i;
    if (v.get_int64().get(i)) return false;
    out = static_cast<double>(i);
    return true;
  }
  if (type == od::number_type::unsigned_integer) {
    std::uint64_t u;
    if (v.get_uint64().get(u)) return false;
    out = static_cast<double>(u);
    return true;
  }
  return !v.get_double().get(out);
}

// read(element, index) for each element of the array `v`, stopping at the first false.
template <class Read>
bool each(od::value v, Read read) {
  od::array a;
  if (v.get_array().get(a)) return false;
  std::size_t i = 0;
  for (auto element_or_error : a) {
    od::value e;
    if (std::move(element_or_error).get(e) || !read(e, i++)) return false;
  }
  return true;
}

template <std::size_t N>
bool numbers(od::value v, std::array<double, N>& out) {
  std::size_t n = 0;
  return each(v, [&](od::value e, std::size_t i) { return i < N && number(e, out[n++]); }) &&
         n == N;
}

// An integer written as one, in [lo, hi], as integer() above.
bool integer(od::value v, std::int64_t lo, std::int64_t hi, std::int64_t& out) {
  od::number_type type;
  return !v.get_number_type().get(type) && type == od::number_type::signed_integer &&
         !v.get_int64().get(out) && out >= lo && out <= hi;
}

template <class T, class Read>
bool read_array(od::value v, std::vector<T>& out, Read read) {
  return each(v, [&](od::value e, std::size_t) { return read(e, out.emplace_back()); });
}

std::optional<Scene> read_on_demand(simdjson::padded_string_view text) {
  od::parser parser;
  od::document doc;
  od::object fields;
  if (parser.iterate(text).get(doc) || doc.get_object().get(fields)) return std::nullopt;
  bool seen[std::size(kKeys)] = {};
  Scene s;
  std::array<double, 2> xy;
  std::array<double, 3> rgb;
  std::int64_t size;
  constexpr std::int64_t kMaxInt = std::numeric_limits<int>::max();
  // The keys in the file's order. The faces' indices are checked against the vertex count after
  // the last key: "vertices" may come after "faces".
  for (auto field : fields) {
    std::string_view key;
    od::value v;
    if (field.unescaped_key().get(key) || field.value().get(v)) return std::nullopt;
    const auto k = static_cast<std::size_t>(std::find(std::begin(kKeys), std::end(kKeys), key) -
                                            std::begin(kKeys));
    if (k == std::size(kKeys) || seen[k]) return std::nullopt;  // not the scene's, or twice
    seen[k] = true;
    bool ok = false;
    switch (k) {
      case 0:
        ok = read_array(v, s.vertices, [&](od::value e, Vec2& p) {
          return numbers(e, xy) && (p = Vec2{xy[0], xy[1]}, true);
        });
        break;
      case 1:
        ok = read_array(v, s.vcolors, [&](od::value e, Color& c) {
          return numbers(e, rgb) && (c = Color{rgb[0], rgb[1], rgb[2]}, true);
        });
        break;
      case 2:
        ok = read_array(v, s.faces, [&](od::value e, std::array<int, 3>& f) {
          std::int64_t index;
          std::size_t n = 0;
          return each(e,
                      [&](od::value i, std::size_t) {
                        return n < 3 && integer(i, 0, kMaxInt, index) &&
                               (f[n++] = static_cast<int>(index), true);
                      }) &&
                 n == 3;
        });
        break;
      case 3:
        ok = read_array(v, s.depth, [](od::value e, double& d) { return number(e, d); });
        break;
      case 4:
      case 5:
        ok = integer(v, 1, kMaxInt, size);
        if (ok) (k == 4 ? s.width : s.height) = static_cast<int>(size);
        break;
      default:
        ok = numbers(v, rgb);
        if (ok) s.background = Color{rgb[0], rgb[1], rgb[2]};
    }
    if (!ok) return std::nullopt;
  }
  // Nothing after the object: On-Demand reports the end as "out of bounds".
  const char* trailing;
  if (doc.current_location().get(trailing) != simdjson::OUT_OF_BOUNDS || !seen[0] || !seen[1] ||
      !seen[2] || !seen[3])
    return std::nullopt;
  for (const auto& f : s.faces)
    for (const int i : f)
      if (static_cast<std::size_t>(i) >= s.vertices.size()) return std::nullopt;
  return s;
}

}  // namespace

std::optional<Scene> read_scene_fast(std::string_view text, std::size_t padding) {
  // simdjson sizes its buffers by the text: a padded copy, 4 bytes of structural index and 8 of
  // tape per byte, and 5/3 of a byte of strings: about 15 bytes per byte, more than the nlohmann
  // DOM that json_input::parse checks against the memory there is (about 2 for a scene file).
  // Where they would not fit, the nlohmann reader reads the text, or refuses it naming the file.
  if (const auto available = available_memory(); available && 15 * text.size() > *available)
    return std::nullopt;
  // Text read by json_input::read_text_file has simdjson's padding after it: used in place.
  std::optional<simdjson::padded_string> copy;
  simdjson::padded_string_view padded;
  if (padding >= simdjson::SIMDJSON_PADDING) {
    padded = simdjson::padded_string_view(text.data(), text.size(), text.size() + padding);
  } else {
    copy.emplace(text);
    padded = *copy;
  }
  if (std::optional<Scene> s = read_on_demand(padded)) return s;
  return read_dom(padded);
}

// Linked whenever scantrace_io is (the linker is told to take this symbol: io/CMakeLists.txt), so
// no program has to remember to register the fast reader.
extern "C" {
extern bool scantrace_fast_scene_reader_registration;
bool scantrace_fast_scene_reader_registration = (register_fast_scene_reader(read_scene_fast), true);
}

namespace detail {
std::optional<Scene> read_scene_on_demand(std::string_view text) {
  return read_on_demand(simdjson::padded_string(text));
}
std::optional<Scene> read_scene_dom(std::string_view text) {
  return read_dom(simdjson::padded_string(text));
}
}  // namespace detail

}  // namespace scantrace
