// The untraced render, alone in its translation unit: the benchmark's two builds then compile
// exactly the same code here except for SCANTRACE_NO_TRACE_HOOKS (the event tracer instantiated
// elsewhere in the program would otherwise change the compiler's unit-wide inlining budget).
#include "src/painter.hpp"

namespace scantrace::bench {

float render_untraced(const Scene& scene, const FillOptions& options) {
  return render(scene, options)(7, 7).r;
}

}  // namespace scantrace::bench
