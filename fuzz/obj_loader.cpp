// Any bytes given to the OBJ loader either give a mesh or an InputError; nothing else may escape.
// A mesh that loads is then carried through the model pipeline — orthographic fit, Lambert
// lighting, culling, the z-buffered render on a small canvas — which must not fail on it either
// (degenerate faces, huge or tiny coordinates, a single point).
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/obj_loader.hpp"
#include "src/painter.hpp"
#include "src/shade_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  scantrace::Mesh mesh;
  try {
    mesh = scantrace::parse_obj(text, "fuzz.obj");
  } catch (const scantrace::InputError&) {
    return 0;
  }
  scantrace::ShadeOptions shade;
  shade.camera.width = shade.camera.height = 64;
  shade.shading = size % 2 ? scantrace::Shading::flat : scantrace::Shading::gouraud;
  const scantrace::Scene scene = scantrace::shade_mesh(mesh, shade);
  scantrace::FillOptions opt{.shading = shade.shading};
  opt.cull = scantrace::Cull::back;
  opt.visibility = scantrace::Visibility::zbuffer;
  const auto image = scantrace::render(scene, opt);
  return image.width() == 64 ? 0 : 1;
}
