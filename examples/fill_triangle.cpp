// Use case: fill one triangle with Gouraud shading and save it.
//
//   fill_triangle [OUT.png]
#include <cstdio>

#include "src/scanline_fill.hpp"
#include "viz/image_file.hpp"

int main(int argc, char** argv) {
  using namespace scantrace;
  const char* out = argc > 1 ? argv[1] : "triangle.png";

  RgbImage canvas(512, 512, Rgb32f{1, 1, 1});  // the course's canvas: 512×512, white
  const FillResult r = fill_triangle(canvas, {Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}},
                                     {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}},
                                     FillOptions{.shading = Shading::gouraud});
  write_png(canvas, out);
  std::printf("%lld pixels on %lld scanlines -> %s\n", static_cast<long long>(r.pixels),
              static_cast<long long>(r.rows), out);
  return r.pixels > 0 ? 0 : 1;
}
