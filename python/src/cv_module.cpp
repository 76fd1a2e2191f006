// _scantrace_cv: the parts of the Python package that need OpenCV, in a module of their own so that
// `import scantrace` never loads OpenCV (its codecs and video I/O bring in hundreds of shared
// libraries): the explanatory video of a trace (scantrace.explain) and the decoding of PNG, JPEG
// and BMP files given to scantrace.diff. `pip install` builds it only when asked
// (SCANTRACE_PYTHON_OPENCV=1); without it those two raise an error naming the missing module.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <optional>
#include <utility>

#include "arrays.hpp"
#include "grade/image_input.hpp"
#include "grade/opencv_decode.hpp"
#include "io/input_error.hpp"
#include "py_trace.hpp"
#include "viz/replay.hpp"

namespace py = pybind11;
using namespace scantrace;
using scantrace::python::PyTrace;

namespace {

py::dict replay(const PyTrace& t, const std::filesystem::path& out, py::handle frame_size,
                double fps, double hold, const std::string& source) {
  viz::ReplayOptions o;
  const auto [w, h] = python::size_argument(frame_size, "frame_size");
  o.size = {w, h};
  if (!std::isfinite(fps) || fps <= 0)
    python::throw_value_error("fps: expected a positive number of frames per second, got " +
                              py::repr(py::float_(fps)).cast<std::string>());
  if (!std::isfinite(hold) || hold < 0)
    python::throw_value_error("hold: expected a time in seconds >= 0, got " +
                              py::repr(py::float_(hold)).cast<std::string>());
  o.fps = fps;
  o.hold = hold;
  o.source = source;
  try {
    viz::validate(o);
  } catch (const std::invalid_argument& e) {
    python::throw_value_error(e.what());
  }
  viz::ReplayResult r;
  {
    py::gil_scoped_release free;
    r = viz::replay(t.trace, out, o);
  }
  py::dict d;
  d["path"] = out;
  d["format"] = r.format;
  d["steps"] = r.steps;
  d["frames"] = r.frames;
  d["seconds"] = r.seconds;
  return d;
}

// An image file as the command's diff reads it, after its pre-check against a canvas of `canvas`
// (width, height; grade/image_precheck.hpp): (uint8 pixels, format, (width, height) declared),
// the pixels None when the header's size decides (nothing decoded: diff reports canvas_size).
py::tuple read_image(const std::filesystem::path& path, std::pair<int, int> canvas) {
  grade::ImageHeader header;
  const std::optional<grade::SubmittedImage> im = grade::read_submitted_image(
      path, grade::decode_with_opencv, canvas.first, canvas.second, header);
  const py::tuple size = py::make_tuple(header.width, header.height);
  if (!im) return py::make_tuple(py::none(), header.format, size);
  py::array_t<std::uint8_t> out({im->pixels.height(), im->pixels.width(), 3});
  std::uint8_t* o = out.mutable_data();
  for (const Rgb32f& p : im->pixels.pixels())
    for (const float v : {p.r, p.g, p.b}) *o++ = static_cast<std::uint8_t>(std::lround(v * 255.0f));
  return py::make_tuple(out, im->format, size);
}

}  // namespace

PYBIND11_MODULE(_scantrace_cv, m) {
  m.doc() = "scantrace's OpenCV parts: explain()'s video and diff()'s image files";
  py::module_::import("scantrace._scantrace");  // registers Trace and InputError
  m.def("replay", &replay, py::arg("trace"), py::arg("out"), py::arg("frame_size"), py::arg("fps"),
        py::arg("hold"), py::arg("source"));
  m.def("read_image", &read_image, py::arg("path"), py::arg("canvas"));
}
