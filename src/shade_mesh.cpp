#include "shade_mesh.hpp"

#include "splitmix64.hpp"

namespace scantrace {

Scene shade_mesh(const Mesh& mesh, const ShadeOptions& opt, ShadeStats* stats,
                 std::vector<int>* face_of) {
  Camera camera = opt.camera;
  const Projection proj = project(mesh, camera);
  const bool gouraud = opt.shading == Shading::gouraud;
  const std::vector<Vec3> averaged = gouraud ? averaged_vertex_normals(mesh) : std::vector<Vec3>{};
  const bool has_colors = mesh.colors.size() == mesh.positions.size();
  SplitMix64 rng(opt.seed);

  Scene scene;
  scene.width = camera.width;
  scene.height = camera.height;
  scene.background = opt.background;
  ShadeStats st;
  if (face_of) face_of->clear();
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f) {
    const auto& t = mesh.faces[f];
    // Drawn for every face, also omitted ones, so that a seed names the same colour per face.
    const Color random{rng.unit(), rng.unit(), rng.unit()};
    if (!proj.in_front[t[0]] || !proj.in_front[t[1]] || !proj.in_front[t[2]]) {
      ++st.faces_behind_eye;
      continue;
    }
    const double flat_intensity = gouraud ? 0.0 : lambert(face_normal(mesh, f), opt.light);
    const int first = static_cast<int>(scene.vertices.size());
    for (int k = 0; k < 3; ++k) {
      const int v = t[k];
      Color base{1, 1, 1};
      if (opt.colors == ColorSource::random)
        base = random;
      else if (opt.colors == ColorSource::file && has_colors)
        base = mesh.colors[v];
      double intensity = flat_intensity;
      if (gouraud) {
        const int given = mesh.face_normals.empty() ? -1 : mesh.face_normals[f][k];
        intensity = lambert(given >= 0 ? mesh.normals[given] : averaged[v], opt.light);
      }
      scene.vertices.push_back(proj.points[v]);
      scene.depth.push_back(proj.depth[v]);
      scene.vcolors.push_back(gamma_encode(base * intensity, opt.gamma));
    }
    scene.faces.push_back({first, first + 1, first + 2});
    if (face_of) face_of->push_back(f);
  }
  if (stats) *stats = st;
  return scene;
}

}  // namespace scantrace
