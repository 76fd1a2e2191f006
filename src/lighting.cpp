#include "lighting.hpp"

#include <algorithm>
#include <cmath>

namespace scantrace {

double lambert(Vec3 n, const Lighting& light) {
  if (!light.enabled) return 1.0;
  const double diffuse = std::max(0.0, dot(normalized(n), normalized(light.direction) * -1.0));
  return light.ambient + (1 - light.ambient) * diffuse;
}

Color gamma_encode(Color c, double gamma) {
  if (gamma == 1) return c;
  const auto e = [&](double v) { return std::pow(std::clamp(v, 0.0, 1.0), 1.0 / gamma); };
  return {e(c.r), e(c.g), e(c.b)};
}

}  // namespace scantrace
