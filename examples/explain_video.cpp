// Use case: the explanatory video of one triangle — trace it in memory, replay the trace into an
// H.264 MP4 (or a directory of PNG frames when OUT ends with '/').
//
//   explain_video [OUT.mp4|OUT_DIR/] [x0 y0 x1 y1 x2 y2]
#include <cstdio>
#include <cstdlib>

#include "trace/record.hpp"
#include "viz/replay.hpp"

int main(int argc, char** argv) {
  using namespace scantrace;
  const char* out = argc > 1 ? argv[1] : "triangle.mp4";
  trace::TriangleInput input;
  input.vertices = {Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}};  // the course's example
  input.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  if (argc == 8)
    for (int i = 0; i < 3; ++i)
      input.vertices[i] = {std::atof(argv[2 + 2 * i]), std::atof(argv[3 + 2 * i])};
  else if (argc > 2) {
    std::fprintf(stderr, "usage: %s [OUT.mp4|OUT_DIR/] [x0 y0 x1 y1 x2 y2]\n", argv[0]);
    return 2;
  }

  const trace::Trace t = trace::record_triangle(input, FillOptions{.shading = Shading::gouraud});
  viz::ReplayOptions options;
  options.size = {960, 540};  // smaller than the default 1280×720: quicker, still legible
  const viz::ReplayResult r = viz::replay(t, out, options);
  std::printf("%zu steps, %zu frames (%s, %.1f s) -> %s\n", r.steps, r.frames, r.format.c_str(),
              r.seconds, out);
  return r.frames > 0 ? 0 : 1;
}
