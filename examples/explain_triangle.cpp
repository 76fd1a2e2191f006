// Use case: the step-by-step trace of one triangle, told in plain words, row by row.
//
//   explain_triangle [x0 y0 x1 y1 x2 y2]     (default: the course example (20,20) (250,80)
//   (300,400))
#include <cstdio>
#include <cstdlib>
#include <string>

#include "trace/record.hpp"

namespace {

using namespace scantrace;
using namespace scantrace::trace;

std::string point(Vec2 p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%g, %g)", p.x, p.y);
  return buf;
}

std::string color(Color c) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.3f, %.3f, %.3f)", c.r, c.g, c.b);
  return buf;
}

void describe_setup(const Trace& t) {
  const TriangleBegin& b = t.triangle_begin(0);
  std::printf("The triangle has vertices v0 %s, v1 %s, v2 %s.\n", point(b.vertices[0]).c_str(),
              point(b.vertices[1]).c_str(), point(b.vertices[2]).c_str());
  std::printf(
      "Edge i joins vertex i to vertex i+1, so edge 0 is v0-v1, edge 1 v1-v2, edge 2 v2-v0.\n\n");
  const EdgeTableEvent& et = t.edge_table(0);
  std::printf(
      "Step 1, the edge table: every edge that is not horizontal, sorted by its top row.\n");
  for (const EdgeEntry& e : et.edges)
    std::printf(
        "  edge %d: from y = %g down to y = %g, starting at x = %g; x moves %.4f per row; "
        "active on rows %lld to %lld\n",
        e.edge, e.y_min, e.y_max, e.x_at_y_min, e.dx_dy, static_cast<long long>(e.first_row),
        static_cast<long long>(e.last_row));
  for (const HorizontalEntry& h : et.horizontal)
    std::printf(
        "  edge %d is horizontal (y = %g): it never crosses a scanline, so it is left out.\n",
        h.edge, h.y);
  std::printf(
      "\nStep 2, the scanlines: on each row the active edges give two crossing points; the\n"
      "pixels whose centres lie from the left point (included) to the right one (excluded)\n"
      "are filled, and the colour is interpolated along the edges, then along the row.\n\n");
}

void describe_row(const Scanline& s) {
  std::printf("Row %lld:", static_cast<long long>(s.y));
  for (int e : s.retired) std::printf(" edge %d has ended and leaves the active list;", e);
  for (int e : s.entered) std::printf(" edge %d starts here and joins the active list;", e);
  if (s.active_points.size() == 2) {
    const trace::ActivePoint& l = s.active_points[0];
    const trace::ActivePoint& r = s.active_points[1];
    std::printf(" edge %d crosses at x = %.3f with colour %s, edge %d at x = %.3f with colour %s.",
                l.edge, l.x, color(l.color).c_str(), r.edge, r.x, color(r.color).c_str());
  }
  if (s.span) {
    std::printf(" Pixels %lld to %lld are filled (%lld pixels)",
                static_cast<long long>(s.span->x_begin), static_cast<long long>(s.span->x_end - 1),
                static_cast<long long>(s.span->size()));
    if (s.span_colors)
      std::printf(", shading from %s to %s", color(s.span_colors->begin).c_str(),
                  color(s.span_colors->end).c_str());
    std::printf(".\n");
  } else {
    std::printf(" No pixel centre lies between the two points, so nothing is filled.\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  TriangleInput input;
  input.vertices = {Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}};
  input.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  if (argc == 7)
    for (int i = 0; i < 3; ++i)
      input.vertices[i] = {std::atof(argv[1 + 2 * i]), std::atof(argv[2 + 2 * i])};
  else if (argc != 1) {
    std::fprintf(stderr, "usage: %s [x0 y0 x1 y1 x2 y2]\n", argv[0]);
    return 2;
  }

  const Trace trace = record_triangle(input, FillOptions{.shading = Shading::gouraud});
  if (const auto skipped = trace.skipped(0)) {
    std::printf("The triangle fills no pixel: %s.\n", skipped->reason.c_str());
    return 0;
  }
  describe_setup(trace);
  for (const Scanline* s : trace.scanlines(0)) describe_row(*s);
  const auto end = trace.triangle_end(0);
  std::printf("\nDone: %lld rows visited, %lld pixels filled.\n", static_cast<long long>(end->rows),
              static_cast<long long>(end->pixels));
  return 0;
}
