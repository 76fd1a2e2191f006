#pragma once
// The Python Trace: a trace and, when it was recorded here, the image its fill drew. Shared by the
// module and the OpenCV one (_scantrace_cv, the video), which receives the same objects.
#include <optional>

#include "src/image.hpp"
#include "trace/trace.hpp"

namespace scantrace::python {

struct PyTrace {
  trace::Trace trace;
  std::optional<RgbImage> image;
};

}  // namespace scantrace::python
