// The extension module behind the `scantrace` Python package (python/scantrace/__init__.py holds
// the public functions, their defaults and docstrings). It depends on the C++ libraries; they know
// nothing of it.
#include <pybind11/pybind11.h>

#include <string_view>

#include "io/input_error.hpp"

namespace scantrace::python {
void bind_options(pybind11::module_& m);
void bind_course(pybind11::module_& m);
void bind_trace(pybind11::module_& m);
void bind_grade(pybind11::module_& m);
void bind_frames(pybind11::module_& m);
}  // namespace scantrace::python

PYBIND11_MODULE(_scantrace, m) {
  m.doc() = "scantrace's C++ core (use the scantrace package, not this module)";
  m.attr("__version__") = SCANTRACE_VERSION;
  // A bad file (scene, model, trace) is a ValueError naming the file and the element. The message
  // may quote the file's bytes, which need not be UTF-8 (a binary file read as a trace): they are
  // shown as \x escapes. pybind11's own translation gave such a message as '' (an empty error).
  static pybind11::exception<scantrace::InputError> input_error(m, "InputError", PyExc_ValueError);
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const scantrace::InputError& e) {
      const std::string_view text = e.what();
      PyObject* message = PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()),
                                               "backslashreplace");
      PyErr_SetObject(input_error.ptr(), message);
      Py_XDECREF(message);
    }
  });
  scantrace::python::bind_options(m);
  scantrace::python::bind_course(m);
  scantrace::python::bind_trace(m);
  scantrace::python::bind_grade(m);
  scantrace::python::bind_frames(m);
}
