#include "scene.hpp"

#include <cmath>
#include <sstream>

namespace scantrace {
namespace {

std::string at(const char* array, std::size_t i) {
  return std::string(array) + "[" + std::to_string(i) + "]";
}

bool finite(Color c) {
  return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}
bool in_unit_range(double v) {
  return v >= 0.0 && v <= 1.0;
}
bool in_unit_range(Color c) {
  return in_unit_range(c.r) && in_unit_range(c.g) && in_unit_range(c.b);
}

std::string color_problem(Color c) {
  if (!finite(c)) return "colour components must be finite numbers";
  std::ostringstream s;
  s << "colour [" << c.r << ", " << c.g << ", " << c.b << "] has a component outside [0, 1]";
  return s.str();
}

}  // namespace

std::optional<SceneProblem> validate(const Scene& scene) {
  if (scene.width <= 0 || scene.height <= 0)
    return SceneProblem{"width/height", "canvas size must be positive, got " +
                                            std::to_string(scene.width) + "x" +
                                            std::to_string(scene.height)};
  if (static_cast<long long>(scene.width) * scene.height > kMaxCanvasPixels)
    return SceneProblem{
        "width/height",
        "canvas of " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
            " pixels exceeds the limit of 2^28 pixels (3 GiB as a float RGB canvas)"};
  if (!finite(scene.background) || !in_unit_range(scene.background))
    return SceneProblem{"background", color_problem(scene.background)};
  const std::size_t n = scene.vertices.size();
  if (scene.vcolors.size() != n)
    return SceneProblem{"vcolors", "has " + std::to_string(scene.vcolors.size()) +
                                       " entries but there are " + std::to_string(n) + " vertices"};
  if (scene.depth.size() != n)
    return SceneProblem{"depth", "has " + std::to_string(scene.depth.size()) +
                                     " entries but there are " + std::to_string(n) + " vertices"};
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(scene.vertices[i].x) || !std::isfinite(scene.vertices[i].y))
      return SceneProblem{at("vertices", i), "coordinate is not a finite number"};
    if (!finite(scene.vcolors[i]) || !in_unit_range(scene.vcolors[i]))
      return SceneProblem{at("vcolors", i), color_problem(scene.vcolors[i])};
    if (!std::isfinite(scene.depth[i]))
      return SceneProblem{at("depth", i), "depth is not a finite number"};
  }
  for (std::size_t f = 0; f < scene.faces.size(); ++f)
    for (int v : scene.faces[f])
      if (v < 0 || static_cast<std::size_t>(v) >= n)
        return SceneProblem{at("faces", f), "vertex index " + std::to_string(v) +
                                                " is out of range (" + std::to_string(n) +
                                                " vertices)"};
  return std::nullopt;
}

}  // namespace scantrace
