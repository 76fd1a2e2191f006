#include "arrays.hpp"

#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

#include <pybind11/stl.h>

#include "src/option_table.hpp"
#include "src/tracer.hpp"

namespace scantrace::python {

void throw_value_error(const std::string& message) {
  throw py::value_error(message);
}
void throw_type_error(const std::string& message) {
  throw py::type_error(message);
}

namespace {

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) {
    if (i) s += ", ";
    s += std::to_string(a.shape(i));
  }
  return s + (a.ndim() == 1 ? ",)" : ")");
}

std::string shape_text(const std::vector<Dim>& shape) {
  std::string s = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    s += i ? ", " : "";
    s += shape[i].any ? std::string(1, shape[i].any) : std::to_string(shape[i].size);
  }
  return s + (shape.size() == 1 ? ",)" : ")");
}

std::string dtype_text(const py::array& a) {
  return py::str(a.dtype()).cast<std::string>();
}

// np.asarray(value): lists, tuples and arrays alike; a value numpy cannot read is a TypeError.
py::array as_numpy(py::handle value, const char* name) {
  if (value.is_none()) throw_type_error(std::string(name) + ": expected an array, got None");
  try {
    return py::module_::import("numpy").attr("asarray")(value);
  } catch (py::error_already_set& e) {
    throw_type_error(std::string(name) + ": cannot be read as an array (" + e.what() + ")");
  }
}

void check_shape(const py::array& a, const char* name, const std::vector<Dim>& shape) {
  bool ok = a.ndim() == static_cast<py::ssize_t>(shape.size());
  for (std::size_t i = 0; ok && i < shape.size(); ++i)
    ok = shape[i].any || a.shape(static_cast<py::ssize_t>(i)) == shape[i].size;
  if (!ok)
    throw_value_error(std::string(name) + ": expected an array of shape " + shape_text(shape) +
                      ", got " + shape_text(a));
  // Scenes and images index with int: a longer dimension is refused before anything is copied.
  for (py::ssize_t i = 0; i < a.ndim(); ++i)
    if (a.shape(i) > INT_MAX)
      throw_value_error(std::string(name) + ": dimension " + std::to_string(i) + " has " +
                        std::to_string(a.shape(i)) + " elements, more than the 2^31 - 1 allowed");
}

// The array as `Target` (C order, converted): numpy's conversion, whose failure (out of memory)
// is reported with the argument's name instead of an unset error.
template <class Target>
Target converted(const py::array& a, const char* name) {
  Target d = Target::ensure(a);
  if (!d) {
    if (PyErr_Occurred()) {
      py::error_already_set e;
      throw_value_error(std::string(name) + ": cannot be converted to " +
                        py::str(py::dtype::of<typename Target::value_type>()).cast<std::string>() +
                        " (" + e.what() + ")");
    }
    throw_value_error(std::string(name) + ": cannot be converted to " +
                      py::str(py::dtype::of<typename Target::value_type>()).cast<std::string>());
  }
  return d;
}

// "vertices[3]" for the row holding flat element i of a C-contiguous array.
std::string element(const char* name, const py::array& a, py::ssize_t i) {
  const py::ssize_t per_row = a.ndim() > 1 ? a.size() / a.shape(0) : 1;
  return std::string(name) + "[" + std::to_string(per_row ? i / per_row : i) + "]";
}

// Whether no value is NaN or infinite: their exponent bits are all ones, and adding one at the
// exponent's lowest bit then carries into the sign bit, which no finite value's sum reaches. Why
// that form: only and, add and or, which the compiler vectorizes; GCC 12 left the comparison form
// (`special |= (bits & e) == e`) one value at a time, and perf put the course scene's render_img
// 1% in it. The loop that names the first bad element runs only when there is one.
bool all_finite(const double* p, py::ssize_t n) {
  constexpr std::uint64_t kExponent = std::uint64_t{0x7ff} << 52, kLowest = std::uint64_t{1} << 52;
  std::uint64_t sums = 0;
  for (py::ssize_t i = 0; i < n; ++i) {
    std::uint64_t bits;
    std::memcpy(&bits, p + i, sizeof bits);
    sums |= (bits & kExponent) + kLowest;
  }
  return (sums >> 63) == 0;
}

// Whether every finite value lies in [0, 1], in the same vectorized way, on the bits: a value
// with the sign bit set, or a positive one whose bits exceed 1.0's (the bits of non-negative
// doubles are ordered as the values), sets the top bit of `bits | (one - bits)`. -0.0 is reported
// outside, although it compares equal to 0: the callers then run the exact check for its message,
// and that check accepts it.
bool all_in_unit_range(const double* p, py::ssize_t n) {
  std::uint64_t one;
  const double one_value = 1.0;
  std::memcpy(&one, &one_value, sizeof one);
  std::uint64_t flags = 0;
  for (py::ssize_t i = 0; i < n; ++i) {
    std::uint64_t bits;
    std::memcpy(&bits, p + i, sizeof bits);
    flags |= bits | (one - bits);
  }
  return (flags >> 63) == 0;
}

// The course's render_img takes (faces, vertices, …), render and the others (vertices, faces, …):
// a K×3 array where the vertices go and an L×2 one where the faces go are the two swapped.
void refuse_swapped(py::handle vertices, py::handle faces) {
  if (vertices.is_none() || faces.is_none()) return;
  const py::array v = as_numpy(vertices, "vertices"), f = as_numpy(faces, "faces");
  if (v.ndim() == 2 && v.shape(1) == 3 && f.ndim() == 2 && f.shape(1) == 2)
    throw_value_error("faces and vertices look swapped (vertices: an array of shape " +
                      shape_text(v) + ", faces: " + shape_text(f) +
                      "): render and trace_scene take (vertices, faces, …); render_img, and a "
                      "scene given to why or diff as a tuple, the course's (faces, vertices, …)");
}

}  // namespace

DoubleArray float_array(py::handle value, const char* name, const std::vector<Dim>& shape) {
  const py::array a = as_numpy(value, name);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw_type_error(std::string(name) + ": expected an array of numbers (float or int), got " +
                     "dtype " + dtype_text(a));
  check_shape(a, name, shape);
  DoubleArray d = converted<DoubleArray>(a, name);  // no copy when a already is C float64
  const double* p = d.data();
  if (all_finite(p, d.size())) return d;
  for (py::ssize_t i = 0; i < d.size(); ++i)
    if (!std::isfinite(p[i]))
      throw_value_error(element(name, d, i) + ": NaN and infinity are not allowed, got " +
                        py::repr(py::float_(p[i])).cast<std::string>());
  return d;
}

IndexArray index_array(py::handle value, const char* name, const std::vector<Dim>& shape) {
  const py::array a = as_numpy(value, name);
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw_type_error(std::string(name) + ": expected an array of integers, got dtype " +
                     dtype_text(a));
  check_shape(a, name, shape);
  if (kind == 'u' && a.itemsize() == 8) {
    // uint64 values above 2^63 - 1 would wrap to negative int64 ("-1" for 2^64 - 1).
    const auto u =
        converted<py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>>(a, name);
    for (py::ssize_t i = 0; i < u.size(); ++i)
      if (u.data()[i] > static_cast<std::uint64_t>(INT64_MAX))
        throw_value_error(element(name, u, i) + ": index " + std::to_string(u.data()[i]) +
                          " is out of range");
  }
  return converted<IndexArray>(a, name);
}

py::array image_array(py::handle value, const char* name) {
  if (!py::isinstance<py::array>(value))
    throw_type_error(std::string(name) + ": expected a numpy array of shape (M, N, 3) to fill " +
                     "in place, got " +
                     py::str(py::type::of(value).attr("__name__")).cast<std::string>());
  const auto a = py::reinterpret_borrow<py::array>(value);
  const char kind = a.dtype().kind();
  if (kind != 'f' || (a.itemsize() != 4 && a.itemsize() != 8))
    throw_type_error(std::string(name) + ": expected a float32 or float64 array, got dtype " +
                     dtype_text(a));
  check_shape(a, name, {'M', 'N', 3});
  if (!a.writeable()) throw_value_error(std::string(name) + ": the array is read-only");
  if (a.shape(0) > INT_MAX || a.shape(1) > INT_MAX || a.shape(0) * a.shape(1) > kMaxCanvasPixels)
    throw_value_error(std::string(name) + ": image of " + shape_text(a) + " is too large");
  return a;
}

std::array<Vec2, 3> triangle_vertices(py::handle value, const char* name) {
  const DoubleArray a = float_array(value, name, {3, 2});
  const double* p = a.data();
  return {Vec2{p[0], p[1]}, Vec2{p[2], p[3]}, Vec2{p[4], p[5]}};
}

std::array<Color, 3> triangle_colors(py::handle value, const char* name) {
  const DoubleArray a = float_array(value, name, {3, 3});
  const double* p = a.data();
  std::array<Color, 3> c{Color{p[0], p[1], p[2]}, Color{p[3], p[4], p[5]}, Color{p[6], p[7], p[8]}};
  for (int i = 0; i < 3; ++i)
    for (double v : {c[i].r, c[i].g, c[i].b})
      if (v < 0 || v > 1)
        throw_value_error(std::string(name) + "[" + std::to_string(i) +
                          "]: colour components must be in [0, 1], got " +
                          py::repr(py::float_(v)).cast<std::string>());
  return c;
}

Color color_argument(py::handle value, const char* name) {
  const DoubleArray a = float_array(value, name, {3});
  const double* p = a.data();
  for (int i = 0; i < 3; ++i)
    if (p[i] < 0 || p[i] > 1)
      throw_value_error(std::string(name) + ": colour components must be in [0, 1], got " +
                        py::repr(py::float_(p[i])).cast<std::string>());
  return {p[0], p[1], p[2]};
}

std::pair<int, int> size_argument(py::handle value, const char* name) {
  const IndexArray a = index_array(value, name, {2});
  const std::int64_t w = a.data()[0], h = a.data()[1];
  if (w <= 0 || h <= 0 || w > INT_MAX || h > INT_MAX || w * h > kMaxCanvasPixels)
    throw_value_error(std::string(name) + ": expected (width, height), both positive and at " +
                      "most 2^28 pixels in all, got (" + std::to_string(w) + ", " +
                      std::to_string(h) + ")");
  return {static_cast<int>(w), static_cast<int>(h)};
}

std::optional<py::int_> integer_value(py::handle value) {
  if (py::isinstance<py::bool_>(value)) return std::nullopt;
  if (py::isinstance<py::int_>(value)) return py::reinterpret_borrow<py::int_>(value);
  // numpy's integer scalars (not np.bool_, which numpy does not count as an integer).
  const py::module_ np = py::module_::import("numpy");
  if (py::isinstance(value, np.attr("integer")))
    return py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
  return std::nullopt;
}

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The course's spelling: a name of the table or its first letter, in any case.
template <class E>
std::optional<E> course_name(const std::string& given) {
  const std::string s = lower(given);
  for (const OptionName<E>& n : option_table<E>().names_)
    if (s == n.name || (s.size() == 1 && s[0] == n.name[0])) return n.value;
  return std::nullopt;
}

template <class E>
py::dict option_dict(py::dict d, const char* part) {
  const OptionTable<E>& t = option_table<E>();
  if (std::strcmp(part, "default") == 0)
    d[t.key] = t.default_name();
  else
    d[t.key] = t.names();
  return d;
}

// Every option's names (or defaults) by key, from the tables of src/option_table.hpp.
py::dict option_entries(const char* part) {
  py::dict d;
  for (auto add : {option_dict<Shading>, option_dict<FillRule>, option_dict<Method>,
                   option_dict<WindingRule>, option_dict<Cull>, option_dict<Visibility>,
                   option_dict<Occlusion>, option_dict<TraceLevel>})
    add(d, part);
  return d;
}

}  // namespace

Shading shading_argument(const std::string& given) {
  if (const std::optional<Shading> s = course_name<Shading>(given)) return *s;
  std::string letters;
  for (const OptionName<Shading>& n : option_table<Shading>().names_)
    letters += {'\'', n.name[0], '\'', ',', ' '};
  throw_value_error("shading: expected " + letters + option_table<Shading>().listed(" or ", "'") +
                    " (in any case), got '" + given + "'");
}

FillRule fill_rule_argument(const std::string& s) {
  if (const std::optional<FillRule> r = parse_option<FillRule>(s)) return *r;
  throw_value_error("fill_rule: expected " + option_table<FillRule>().listed(" or ", "'") +
                    ", got '" + s + "'");
}

void bind_options(py::module_& m) {
  m.def(
      "option_names", [] { return option_entries("names"); },
      "Each option's names by key (shading, fill_rule, method, ...), as the C++ tables list them.");
  m.def(
      "option_defaults", [] { return option_entries("default"); },
      "Each option's default name by key.");
}

FillOptions fill_options(const std::string& shading, const std::string& fill_rule) {
  FillOptions opt;
  opt.shading = shading_argument(shading);
  opt.fill_rule = fill_rule_argument(fill_rule);
  return opt;
}

Scene scene_from_arrays(py::handle vertices, py::handle faces, py::handle vcolors, py::handle depth,
                        std::pair<int, int> size, Color background) {
  refuse_swapped(vertices, faces);
  const DoubleArray v = float_array(vertices, "vertices", {'L', 2});
  const py::ssize_t n = v.shape(0);
  const DoubleArray c = float_array(vcolors, "vcolors", {n == 0 ? Dim('L') : Dim(n), 3});
  const IndexArray f = index_array(faces, "faces", {'K', 3});
  // depth: the course gives it as L or L×1.
  py::array d0 = as_numpy(depth, "depth");
  if (d0.ndim() == 2 && d0.shape(1) == 1) d0 = d0.attr("reshape")(-1);
  const DoubleArray d = float_array(d0, "depth", {n == 0 ? Dim('L') : Dim(n)});

  Scene scene;
  scene.width = size.first;
  scene.height = size.second;
  scene.background = background;
  scene.vertices.resize(static_cast<std::size_t>(n));
  scene.vcolors.resize(static_cast<std::size_t>(n));
  scene.depth.assign(d.data(), d.data() + n);
  const double* pv = v.data();
  const double* pc = c.data();
  for (py::ssize_t i = 0; i < n; ++i) {
    scene.vertices[i] = {pv[2 * i], pv[2 * i + 1]};
    scene.vcolors[i] = {pc[3 * i], pc[3 * i + 1], pc[3 * i + 2]};
  }
  const py::ssize_t k = f.shape(0);
  scene.faces.resize(static_cast<std::size_t>(k));
  const std::int64_t* pf = f.data();
  // The indices copied and checked in one pass without an exit (an index outside [0, n) is one
  // at or above n as an unsigned number); the first bad face is looked for only if there is one.
  // An index in [0, n) leaves the sign bit of both `index` and `n - 1 - index` clear; a negative
  // one sets it in the first, one at or above n in the second (and/or/sub only, as all_finite).
  std::uint64_t flags = 0;
  const auto last = static_cast<std::uint64_t>(n - 1);
  for (py::ssize_t i = 0; i < k; ++i) {
    const auto a = static_cast<std::uint64_t>(pf[3 * i]),
               b = static_cast<std::uint64_t>(pf[3 * i + 1]),
               c = static_cast<std::uint64_t>(pf[3 * i + 2]);
    flags |= a | b | c | (last - a) | (last - b) | (last - c);
    scene.faces[i] = {static_cast<int>(a), static_cast<int>(b), static_cast<int>(c)};
  }
  const bool out_of_range = (flags >> 63) != 0;
  for (py::ssize_t i = 0; out_of_range && i < 3 * k; ++i)
    if (pf[i] < 0 || pf[i] >= n)
      throw_value_error("faces[" + std::to_string(i / 3) + "]: vertex index " +
                        std::to_string(pf[i]) + " is out of range (" + std::to_string(n) +
                        " vertices)");
  // What validate() checks beyond the above (finite values, indices, size and background are
  // checked already): the colours' range. It runs, for its message, only when that fails.
  if (!all_in_unit_range(pc, 3 * n))
    if (const auto problem = validate(scene))
      throw_value_error(problem->element + ": " + problem->problem);
  return scene;
}

}  // namespace scantrace::python
