// Renders a one-triangle scene with scantrace::core alone and checks every pixel against the
// hand-derived coverage. Exit status 0 = as expected.
#include <cstdio>

#include <scantrace/src/painter.hpp>

int main() {
  scantrace::Scene scene;
  scene.width = scene.height = 16;
  scene.vertices = {{0, 0}, {8, 0}, {0, 8}};
  scene.vcolors = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  scene.faces = {{0, 1, 2}};
  scene.depth = {1, 1, 1};
  const auto image = scantrace::render(scene);

  // Pixel (x, y) is sampled at the integer point (x, y) (docs/usage.md "Scene files"). The hypotenuse
  // x + y = 8 is a right edge, excluded by the top-left rule; the top edge y = 0 and the left
  // edge x = 0 are included. So the pixel is red iff x + y <= 7: 8 + 7 + … + 1 = 36 pixels; the
  // rest stay white.
  int red = 0, wrong = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      const auto p = image(x, y);
      const bool inside = x + y <= 7;
      const bool is_red = p.r == 1 && p.g == 0 && p.b == 0;
      const bool is_white = p.r == 1 && p.g == 1 && p.b == 1;
      red += is_red;
      if (inside ? !is_red : !is_white) ++wrong;
    }
  std::printf("render_core: %d red pixels, %d wrong\n", red, wrong);
  return red == 36 && wrong == 0 ? 0 : 1;
}
