#pragma once
// Arguments from Python checked and turned into what the C++ library takes. Every problem is a
// TypeError (wrong kind of value or dtype) or a ValueError (wrong shape, NaN or infinity, an index
// out of range) whose message starts with the argument's name and says what was expected and what
// was given: "vertices: expected an array of shape (3, 2), got (2, 3)".
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "src/fill_options.hpp"
#include "src/scene.hpp"

namespace scantrace::python {

namespace py = pybind11;

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IndexArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

// A dimension of an expected shape: a fixed size, or any (written with its letter, e.g. 'L').
struct Dim {
  py::ssize_t size = -1;
  char any = 0;
  Dim(int s) : size(s) {}   // NOLINT: Dim{3} and 3 read the same in a shape list
  Dim(long s) : size(s) {}  // NOLINT: an array's own length (py::ssize_t), never narrowed
  Dim(char letter) : any(letter) {}
};

// `value` as a C-contiguous float64 array of the given shape: no copy when it already is one.
// Refuses non-numeric and boolean dtypes (TypeError), other shapes and non-finite values
// (ValueError).
// An integer from Python: an int or a numpy integer scalar (x and y from np.nonzero are
// np.int64), never a bool; nullopt for anything else, whose message the caller words.
std::optional<py::int_> integer_value(py::handle value);

DoubleArray float_array(py::handle value, const char* name, const std::vector<Dim>& shape);
// The same for indices: integer dtypes only.
IndexArray index_array(py::handle value, const char* name, const std::vector<Dim>& shape);

// A float32 or float64 array of shape (M, N, 3) that the fill may write (f_shading's `img`).
py::array image_array(py::handle value, const char* name);

std::array<Vec2, 3> triangle_vertices(py::handle value, const char* name = "vertices");
std::array<Color, 3> triangle_colors(py::handle value, const char* name = "vcolors");
Color color_argument(py::handle value, const char* name);
// (width, height), both positive.
std::pair<int, int> size_argument(py::handle value, const char* name = "size");

// A shading's name or its first letter, in any case ('F', 'Flat', 'g'); src/option_table.hpp.
Shading shading_argument(const std::string& value);
FillRule fill_rule_argument(const std::string& value);  // a fill rule's name
// _scantrace.option_names() and option_defaults(): the tables of src/option_table.hpp.
void bind_options(py::module_& m);
FillOptions fill_options(const std::string& shading, const std::string& fill_rule);

// A scene from the course's arrays, validated like a scene file (scene.hpp's validate()).
Scene scene_from_arrays(py::handle vertices, py::handle faces, py::handle vcolors, py::handle depth,
                        std::pair<int, int> size, Color background);

[[noreturn]] void throw_value_error(const std::string& message);
[[noreturn]] void throw_type_error(const std::string& message);

}  // namespace scantrace::python
