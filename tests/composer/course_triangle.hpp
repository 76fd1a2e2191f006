#pragma once
// The course's example triangle, traced at scanline level with Gouraud shading: the trace the
// composer tests replay (47 steps at the default plan).
#include "trace/record.hpp"

namespace scantrace::test {

inline trace::Trace course_triangle_trace() {
  trace::TriangleInput t;
  t.vertices = {Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}};
  t.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  t.width = t.height = 512;
  FillOptions options;
  options.shading = Shading::gouraud;
  return trace::record_triangle(t, options, {});
}

}  // namespace scantrace::test
