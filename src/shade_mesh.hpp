#pragma once
// A lit mesh becomes the course's Scene (2-D vertices, depths, per-vertex colours, faces), so that
// render, trace, explain and replay work on models unchanged.
//
// Every face gets its own three scene vertices (nothing shared). That is what lets one face be
// lit as a whole (flat: the three corners carry the face's colour) while its neighbour differs,
// and it costs nothing in coverage: the unshared corners have the same positions, so the top-left
// rule still gives every pixel of the mesh to exactly one face, in painter's order and z-buffer.
#include <cstdint>

#include "camera.hpp"
#include "fill_options.hpp"
#include "lighting.hpp"
#include "mesh.hpp"
#include "scene.hpp"

namespace scantrace {

// Base colour of the surface, before lighting.
// file: the mesh's vertex colours (white where it has none); random: one colour per face from
// `seed` (the classic first picture, with lighting off); white: plain.
enum class ColorSource { file, random, white };

struct ShadeOptions {
  ColorSource colors = ColorSource::file;
  std::uint64_t seed = 1;
  Lighting light;
  // flat: one intensity per face, from its geometric normal; gouraud: one per corner, from the
  // corner's normal (given in the file, or averaged from the faces around the vertex).
  Shading shading = Shading::gouraud;
  // Applied to each shaded vertex colour: flat faces are then exactly encoded; Gouraud
  // interpolates encoded values (what a scanline renderer without a float framebuffer does), so
  // that the trace still narrates the very pixels of the image.
  double gamma = 1.0;
  Camera camera;
  Color background{1, 1, 1};
};

struct ShadeStats {
  long long faces_behind_eye = 0;  // perspective: omitted, a vertex is not in front of the eye
};

// Scene face i is mesh face `face_of[i]` (they differ only when faces were omitted).
Scene shade_mesh(const Mesh& mesh, const ShadeOptions& options, ShadeStats* stats = nullptr,
                 std::vector<int>* face_of = nullptr);

}  // namespace scantrace
