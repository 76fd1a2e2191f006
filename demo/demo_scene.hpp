#pragma once
#include "src/scene.hpp"

namespace scantrace {

// The built-in default scene of `scantrace demo`, generated (deterministically) rather than read:
// a jittered grid mesh coloured by a hue wheel (hundreds of triangles sharing edges, so seams
// would show), a sun drawn as a fan of thin triangles around one vertex, and three large
// overlapping Gouraud triangles at different depths for the painter's algorithm to sort.
Scene demo_scene();

// The single triangle the demo explains step by step: the course report's example,
// (20,20), (250,80), (300,400) with red, green and blue vertices.
struct DemoTriangle {
  std::array<Vec2, 3> vertices{Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}};
  std::array<Color, 3> colors{Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
};

}  // namespace scantrace
