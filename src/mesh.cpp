#include "mesh.hpp"

namespace scantrace {
namespace {

Vec3 area_normal(const Mesh& m, int f) {
  const auto& t = m.faces[f];
  const Vec3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
  return cross(b - a, c - a);
}

}  // namespace

Vec3 face_normal(const Mesh& mesh, int f) {
  return normalized(area_normal(mesh, f));
}

std::vector<Vec3> averaged_vertex_normals(const Mesh& mesh) {
  std::vector<Vec3> n(mesh.positions.size());
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f) {
    const Vec3 a = area_normal(mesh, f);
    for (int v : mesh.faces[f]) n[v] += a;
  }
  for (Vec3& v : n) v = normalized(v);
  return n;
}

}  // namespace scantrace
