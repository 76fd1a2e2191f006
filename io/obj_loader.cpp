#include "io/obj_loader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>
#include <string_view>

#include <tiny_obj_loader.h>

#include "io/json_input.hpp"
#include "src/std_compat.hpp"
#include "io/memory_budget.hpp"

namespace scantrace {
namespace {

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t b = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
  return out;
}

// The checks tinyobjloader does not make, with the line they concern.
class Checker {
 public:
  explicit Checker(const std::string& name) : name_(name) {}

  void line(std::string_view text, long number) {
    number_ = number;
    const auto t = tokens(text);
    if (t.empty() || t[0].front() == '#') return;
    if (t[0] == "v")
      vertex(t);
    else if (t[0] == "vn")
      numbers(t, 3, 3), ++normals_;
    else if (t[0] == "vt")
      numbers(t, 1, 3), ++texcoords_;
    else if (t[0] == "f")
      face(t);
  }

  bool all_vertices_coloured() const { return vertices_ > 0 && coloured_ == vertices_; }

 private:
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(name_ + ":" + std::to_string(number_), "", problem);
  }

  std::vector<double> numbers(const std::vector<std::string_view>& t, std::size_t lo,
                              std::size_t hi) const {
    const std::string what(t[0]);
    if (t.size() - 1 < lo || t.size() - 1 > hi)
      fail(what + ": expected " + std::to_string(lo) +
           (lo == hi ? "" : " to " + std::to_string(hi)) + " numbers, got " +
           std::to_string(t.size() - 1));
    std::vector<double> out;
    for (std::size_t i = 1; i < t.size(); ++i) {
      double v = 0;
      const auto [end, ec] = from_chars_double(t[i].data(), t[i].data() + t[i].size(), v);
      if (ec != std::errc() || end != t[i].data() + t[i].size() || !std::isfinite(v))
        fail(what + ": \"" + std::string(t[i]) + "\" is not a finite number");
      out.push_back(v);
    }
    return out;
  }

  void vertex(const std::vector<std::string_view>& t) {
    // x y z, x y z w, or x y z r g b (the common vertex-colour extension).
    const std::vector<double> v = numbers(t, 3, 6);
    if (v.size() == 5) fail("v: expected x y z [w] or x y z r g b, got 5 numbers");
    if (v.size() == 6) {
      for (int k = 3; k < 6; ++k)
        if (v[k] < 0 || v[k] > 1)
          fail("v: colour component " + std::string(t[k + 1]) + " is outside [0, 1]");
      ++coloured_;
    }
    ++vertices_;
  }

  // One OBJ index: 1-based, or negative counting back from the last one defined so far.
  void index(std::string_view text, long count, const char* what, const char* plural,
             std::string_view corner) {
    long i = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), i);
    if (ec != std::errc() || end != text.data() + text.size())
      fail("f: corner \"" + std::string(corner) + "\": \"" + std::string(text) +
           "\" is not an integer index");
    const long resolved = i < 0 ? count + i + 1 : i;
    if (i == 0 || resolved < 1 || resolved > count)
      fail("f: corner \"" + std::string(corner) + "\": " + what + " index " + std::to_string(i) +
           " is out of range (" + std::to_string(count) + " " + plural + " so far)");
  }

  void face(const std::vector<std::string_view>& t) {
    if (t.size() < 4)
      fail("f: a face needs at least 3 corners, got " + std::to_string(t.size() - 1));
    for (std::size_t c = 1; c < t.size(); ++c) {
      // v, v/vt, v//vn or v/vt/vn
      std::string_view parts[3];
      int n = 0;
      std::string_view rest = t[c];
      for (;;) {
        const std::size_t slash = rest.find('/');
        if (n == 3) fail("f: corner \"" + std::string(t[c]) + "\" has more than v/vt/vn");
        parts[n++] = rest.substr(0, slash);
        if (slash == std::string_view::npos) break;
        rest = rest.substr(slash + 1);
      }
      index(parts[0], vertices_, "vertex", "vertices", t[c]);
      if (n > 1 && !parts[1].empty()) index(parts[1], texcoords_, "texcoord", "texcoords", t[c]);
      if (n > 2 && !parts[2].empty()) index(parts[2], normals_, "normal", "normals", t[c]);
    }
  }

  std::string name_;
  long number_ = 0;
  long vertices_ = 0, coloured_ = 0, normals_ = 0, texcoords_ = 0;
};

}  // namespace

Mesh parse_obj(const std::string& text, const std::string& name,
               std::vector<std::string>* warnings) {
  Checker check(name);
  long number = 0;
  for (std::size_t b = 0; b < text.size();) {
    std::size_t e = text.find('\n', b);
    if (e == std::string::npos) e = text.size();
    check.line(std::string_view(text).substr(b, e - b), ++number);
    b = e + 1;
  }

  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = true;
  tinyobj::ObjReader reader;
  // No material text: the renderer does not use materials, and a model must not make us read
  // files it names.
  const bool ok = reader.ParseFromString(text, "", config);
  if (!ok) throw InputError(name, "", "tinyobjloader: " + reader.Error());
  if (warnings && !reader.Warning().empty()) {
    std::stringstream in(reader.Warning());
    for (std::string w; std::getline(in, w);)
      if (!w.empty() && w != ".") warnings->push_back(name + ": tinyobjloader: " + w);
  }

  const tinyobj::attrib_t& a = reader.GetAttrib();
  Mesh m;
  const std::size_t nv = a.vertices.size() / 3;
  for (std::size_t i = 0; i < nv; ++i)
    m.positions.push_back({a.vertices[3 * i], a.vertices[3 * i + 1], a.vertices[3 * i + 2]});
  // tinyobjloader fills in white for vertices without a colour; only a file that colours every
  // vertex is taken to have colours.
  if (check.all_vertices_coloured() && a.colors.size() == 3 * nv)
    for (std::size_t i = 0; i < nv; ++i)
      m.colors.push_back({a.colors[3 * i], a.colors[3 * i + 1], a.colors[3 * i + 2]});
  for (std::size_t i = 0; i < a.normals.size() / 3; ++i)
    m.normals.push_back({a.normals[3 * i], a.normals[3 * i + 1], a.normals[3 * i + 2]});
  bool any_normal = false;
  for (const tinyobj::shape_t& s : reader.GetShapes()) {
    const auto& idx = s.mesh.indices;
    for (std::size_t i = 0; i + 2 < idx.size(); i += 3) {
      m.faces.push_back({idx[i].vertex_index, idx[i + 1].vertex_index, idx[i + 2].vertex_index});
      m.face_normals.push_back(
          {idx[i].normal_index, idx[i + 1].normal_index, idx[i + 2].normal_index});
      any_normal |=
          idx[i].normal_index >= 0 || idx[i + 1].normal_index >= 0 || idx[i + 2].normal_index >= 0;
    }
  }
  if (!any_normal || m.normals.empty()) m.face_normals.clear(), m.normals.clear();
  if (m.faces.empty()) throw InputError(name, "", "the model has no faces");
  // The line check above reads lines as '\n' ends them; tinyobjloader also ends a line at a lone
  // '\r', so a face can reach it unchecked (found by fuzzing: "v1 2 1\rf 1 1 21"). Whatever the
  // parser made of the text, no index may leave the arrays.
  const auto valid = [](int i, std::size_t n) { return i >= 0 && static_cast<std::size_t>(i) < n; };
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      if (!valid(m.faces[f][k], m.positions.size()))
        throw InputError(name, "face " + std::to_string(f + 1),
                         "vertex index " + std::to_string(m.faces[f][k] + 1) +
                             " is out of range (" + std::to_string(m.positions.size()) +
                             " vertices; lines ended by a lone carriage return count too)");
      if (!m.face_normals.empty() && m.face_normals[f][k] >= 0 &&
          !valid(m.face_normals[f][k], m.normals.size()))
        throw InputError(name, "face " + std::to_string(f + 1),
                         "normal index " + std::to_string(m.face_normals[f][k] + 1) +
                             " is out of range (" + std::to_string(m.normals.size()) + " normals)");
    }
  return m;
}

Mesh load_obj(const std::filesystem::path& file, std::vector<std::string>* warnings) {
  // Read as the scene files are: a FIFO or a device refused, the size against the memory budget.
  return within_memory(file.string(), [&] {
    return parse_obj(json_input::read_text_file(file), file.string(), warnings);
  });
}

bool is_obj_file(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".obj";
}

}  // namespace scantrace
