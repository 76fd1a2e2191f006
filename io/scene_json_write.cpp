// Writing scene files in the layout load_scene reads, one array element per line.
#include <string>

#include <nlohmann/json.hpp>

#include "io/atomic_write.hpp"
#include "io/scene_json.hpp"

namespace scantrace {
namespace {

using nlohmann::json;

json rgb(Color c) {
  return json::array({c.r, c.g, c.b});
}

// `"key": [\n    e0,\n    e1\n  ]` with each element compact on its own line.
template <class T, class ToJson>
void append_array(std::string& out, const char* key, const std::vector<T>& items, ToJson to_json,
                  bool last = false) {
  out += "  \"";
  out += key;
  out += "\": [";
  for (std::size_t i = 0; i < items.size(); ++i) {
    out += i == 0 ? "\n    " : ",\n    ";
    out += to_json(items[i]).dump();
  }
  out += items.empty() ? "]" : "\n  ]";
  out += last ? "\n" : ",\n";
}

}  // namespace

std::string scene_to_json(const Scene& s) {
  // nlohmann writes doubles with max_digits10 significant digits, so they read back exactly.
  std::string out = "{\n";
  out += "  \"width\": " + std::to_string(s.width) + ",\n";
  out += "  \"height\": " + std::to_string(s.height) + ",\n";
  out += "  \"background\": " + rgb(s.background).dump() + ",\n";
  append_array(out, "vertices", s.vertices, [](Vec2 v) { return json::array({v.x, v.y}); });
  append_array(out, "vcolors", s.vcolors, rgb);
  append_array(out, "faces", s.faces, [](const std::array<int, 3>& f) {
    return json::array({f[0], f[1], f[2]});
  });
  append_array(
      out, "depth", s.depth, [](double d) { return json(d); }, /*last=*/true);
  out += "}\n";
  return out;
}

void save_scene(const Scene& scene, const std::filesystem::path& file) {
  write_file_atomically(file, scene_to_json(scene));
}

}  // namespace scantrace
