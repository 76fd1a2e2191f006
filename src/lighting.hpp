#pragma once
// Lambert's diffuse lighting with an ambient term, and gamma encoding.
//
// `direction` is the way the light travels (tinyrenderer's light_dir): (0, 0, −1) shines from the
// viewer into the screen, so a face whose normal points at the viewer (+z) is fully lit.
//   intensity = ambient + (1 − ambient) · max(0, n · (−direction))       (n, direction unit)
// so the result stays in [ambient, 1] and a colour times it stays in [0, 1].
#include "color.hpp"
#include "vec3.hpp"

namespace scantrace {

struct Lighting {
  bool enabled = true;
  Vec3 direction{0, 0, -1};
  double ambient = 0.1;
};

// The intensity for a surface with normal `n` (need not be unit); 1 when lighting is off.
double lambert(Vec3 n, const Lighting& light);

// c^(1/gamma) per channel: linear light to the encoded values an 8-bit image stores
// (gamma 1: unchanged).
Color gamma_encode(Color c, double gamma);

}  // namespace scantrace
