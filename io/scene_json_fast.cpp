#include "io/scene_json_fast.hpp"

#include <simdjson.h>

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

}  // namespace

std::optional<Scene> read_scene_fast(std::string_view text) {
  // simdjson sizes its buffers by the text: a padded copy, 4 bytes of structural index and 8 of
  // tape per byte, and 5/3 of a byte of strings: about 15 bytes per byte, more than the nlohmann
  // DOM that json_input::parse checks against the memory there is (about 2 for a scene file).
  // Where they would not fit, the nlohmann reader reads the text, or refuses it naming the file.
  if (const auto available = available_memory(); available && 15 * text.size() > *available)
    return std::nullopt;
  simdjson::dom::parser parser;
  element root;
  object fields;
  if (parser.parse(text.data(), text.size()).get(root) || root.get_object().get(fields))
    return std::nullopt;
  // The keys it reads, each given once (nlohmann and simdjson differ on which of two wins).
  constexpr std::string_view kKeys[] = {"vertices", "vcolors", "faces",     "depth",
                                        "width",    "height",  "background"};
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

}  // namespace scantrace
