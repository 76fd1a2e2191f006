#include "io/pickled_scene.hpp"

#include <climits>
#include <cmath>

#include "io/input_error.hpp"
#include "io/npy_reader.hpp"
#include "io/pickle_reader.hpp"

namespace scantrace {

bool looks_pickled(std::string_view bytes) {
  return bytes.substr(0, 6) == "\x93NUMPY" ||
         (bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x80 && bytes[1] >= 2 &&
          bytes[1] <= 5);
}

namespace {

constexpr const char* kKeys[] = {"vertices", "vcolors", "faces", "depth"};

class SceneArrays {
 public:
  SceneArrays(std::map<std::string, PickledArray> arrays, const std::string& name)
      : a_(std::move(arrays)), name_(name) {}

  Scene read() {
    for (const auto& [key, array] : a_) {
      bool known = false;
      for (const char* k : kKeys) known = known || key == k;
      if (!known) fail(key, "is not a key of the course's scene (vertices, vcolors, faces, depth)");
    }
    const PickledArray& v = array("vertices", "if", 2);
    const PickledArray& c = array("vcolors", "f", 3);
    const PickledArray& f = array("faces", "iu", 3);
    const PickledArray& d = array("depth", "if", 0);
    const std::uint64_t n = v.shape[0];
    if (c.shape[0] != n) fail("vcolors", "has " + rows(c) + ", vertices " + rows(v));
    if (d.size() != n || (d.shape.size() == 2 && d.shape[1] != 1) || d.shape.size() > 2)
      fail("depth", "has shape " + shape(d) + ", expected (" + std::to_string(n) + ",) or (" +
                        std::to_string(n) + ", 1)");
    Scene s;  // the course's canvas: 512×512 on white (Scene's defaults)
    s.vertices.resize(n);
    s.vcolors.resize(n);
    s.depth.resize(n);
    for (std::uint64_t i = 0; i < n; ++i) {
      s.vertices[i] = {finite(v, 2 * i, "vertices"), finite(v, 2 * i + 1, "vertices")};
      s.vcolors[i] = {finite(c, 3 * i, "vcolors"), finite(c, 3 * i + 1, "vcolors"),
                      finite(c, 3 * i + 2, "vcolors")};
      s.depth[i] = finite(d, i, "depth");
    }
    s.faces.resize(f.shape[0]);
    for (std::uint64_t i = 0; i < f.shape[0]; ++i)
      for (int j = 0; j < 3; ++j) {
        std::int64_t index = -1;
        const bool fits = f.integer_at(3 * i + j, index);
        if (!fits || index < 0 || static_cast<std::uint64_t>(index) >= n)
          fail("faces[" + std::to_string(i) + "]", "vertex index " + f.integer_text(3 * i + j) +
                                                       " is out of range (" + std::to_string(n) +
                                                       " vertices)");
        s.faces[i][j] = static_cast<int>(index);
      }
    return s;
  }

 private:
  [[noreturn]] void fail(const std::string& element, const std::string& problem) const {
    throw InputError(name_, element, problem);
  }
  static std::string shape(const PickledArray& a) {
    std::string s = "(";
    for (std::size_t k = 0; k < a.shape.size(); ++k)
      s += (k ? ", " : "") + std::to_string(a.shape[k]);
    return s + (a.shape.size() == 1 ? ",)" : ")");
  }
  static std::string rows(const PickledArray& a) { return std::to_string(a.shape[0]) + " rows"; }

  // The array `key`, of one of the dtype kinds `kinds`, of shape N×columns (columns 0: N or N×1).
  const PickledArray& array(const char* key, const char* kinds, std::uint64_t columns) const {
    const auto it = a_.find(key);
    if (it == a_.end()) fail("", std::string("missing key '") + key + "'");
    const PickledArray& a = it->second;
    if (std::string(kinds).find(a.kind) == std::string::npos)
      fail(key, "dtype " + a.dtype() + " is not " +
                    (std::string(kinds) == "f" ? "a float type" : "a number type"));
    const bool ok = columns ? a.shape.size() == 2 && a.shape[1] == columns : !a.shape.empty();
    if (!ok) fail(key, "has shape " + shape(a) + ", expected (N, " + std::to_string(columns) + ")");
    if (a.shape[0] > INT_MAX) fail(key, "has more than 2^31 rows");
    return a;
  }

  double finite(const PickledArray& a, std::uint64_t i, const char* key) const {
    const double x = a.at(i);
    if (!std::isfinite(x))
      fail(std::string(key) + "[" + std::to_string(a.shape.size() > 1 ? i / a.shape[1] : i) + "]",
           std::isnan(x) ? "NaN" : "infinite value");
    return x;
  }

  std::map<std::string, PickledArray> a_;
  const std::string& name_;
};

}  // namespace

Scene parse_pickled_scene(std::string_view bytes, const std::string& name) {
  std::string_view pickle = bytes;
  if (bytes.substr(0, 6) == "\x93NUMPY") {
    const NpyHeader h = parse_npy_header(bytes, name);
    if (h.descr != "|O" && h.descr != "O")
      throw InputError(name, "header descr",
                       "dtype '" + h.descr +
                           "': a scene .npy holds a pickled dict of arrays (the course's hw1.npy), "
                           "this one holds a plain array");
    if (!h.shape.empty())
      throw InputError(name, "header shape",
                       "a scene .npy holds one dict (shape ()), not an array");
    pickle = bytes.substr(h.data_offset);
  } else if (!looks_pickled(bytes)) {
    throw InputError(name, "",
                     "neither a .npy file nor a pickle of protocol 2 to 5 (np.save writes 3); "
                     "protocols 0 and 1 are not read");
  }
  return SceneArrays(read_pickled_arrays(pickle, name), name).read();
}

}  // namespace scantrace
