// The extension module behind the `scantrace` Python package (python/scantrace/__init__.py holds
// the public functions, their defaults and docstrings). It depends on the C++ libraries; they know
// nothing of it.
#include <pybind11/pybind11.h>

#include "io/input_error.hpp"

namespace scantrace::python {
void bind_course(pybind11::module_& m);
void bind_trace(pybind11::module_& m);
void bind_grade(pybind11::module_& m);
}  // namespace scantrace::python

PYBIND11_MODULE(_scantrace, m) {
  m.doc() = "scantrace's C++ core (use the scantrace package, not this module)";
  m.attr("__version__") = SCANTRACE_VERSION;
  // A bad file (scene, model, trace) is a ValueError naming the file and the element.
  pybind11::register_exception<scantrace::InputError>(m, "InputError", PyExc_ValueError);
  scantrace::python::bind_course(m);
  scantrace::python::bind_trace(m);
  scantrace::python::bind_grade(m);
}
