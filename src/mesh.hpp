#pragma once
// A triangle mesh in model space, as an OBJ file or a generator gives it: shared positions,
// optional per-position colours, optional per-corner normals. Faces are counter-clockwise seen
// from the outside (OBJ's convention), which is what back-face culling relies on.
#include <array>
#include <vector>

#include "color.hpp"
#include "vec3.hpp"

namespace scantrace {

struct Mesh {
  std::vector<Vec3> positions;
  std::vector<Color> colors;  // empty, or one per position
  std::vector<std::array<int, 3>> faces;
  // Optional normals given with the mesh: `normals` is a pool, `face_normals[f][k]` the normal of
  // corner k of face f (−1: none given). Empty when the mesh has none.
  std::vector<Vec3> normals;
  std::vector<std::array<int, 3>> face_normals;
};

// The geometric normal of face f: unit, pointing to the side from which the face is
// counter-clockwise (zero for a degenerate face).
Vec3 face_normal(const Mesh& mesh, int f);

// One unit normal per position: the area-weighted mean of the normals of the faces around it
// (the unnormalised cross products summed, so larger faces count more).
std::vector<Vec3> averaged_vertex_normals(const Mesh& mesh);

}  // namespace scantrace
