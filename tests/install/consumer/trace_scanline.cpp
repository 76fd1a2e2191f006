// Records a trace with scantrace::trace and asserts on one scanline, derived by hand; checks that
// the trace's generator is the installed package's version. Exit status 0 = as expected.
#include <cstdio>
#include <string>

#include <scantrace/trace/record.hpp>

int main() {
  scantrace::trace::TriangleInput triangle;
  triangle.vertices = {{{2, 1}, {12, 1}, {2, 11}}};
  triangle.colors = {{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}};
  triangle.width = triangle.height = 16;
  const auto trace = scantrace::trace::record_triangle(triangle, scantrace::FillOptions{});

  // Row 4 is sampled at y = 4: the left edge x = 2 and the hypotenuse x + y = 13 cross it at
  // x = 2 and x = 9. Pixel x is sampled at x; 2 is on a left edge (inside), 9 on a right edge
  // (outside): pixels 2..8, the half-open span [2, 9).
  const auto& row = trace.scanline(0, 4);
  const bool span_ok = row.span && row.span->x_begin == 2 && row.span->x_end == 9;
  const bool points_ok = row.active_points.size() == 2 && row.active_points[0].x == 2.0 &&
                         row.active_points[1].x == 9.0;
  const std::string generator = trace.header().generator;
  const bool generator_ok = generator == std::string("scantrace ") + PACKAGE_VERSION;
  std::printf("trace_scanline: span [%lld, %lld), points %zu, generator \"%s\"\n",
              row.span ? static_cast<long long>(row.span->x_begin) : -1LL,
              row.span ? static_cast<long long>(row.span->x_end) : -1LL, row.active_points.size(),
              generator.c_str());
  return span_ok && points_ok && generator_ok ? 0 : 1;
}
