#include "grade/face_id_render.hpp"

#include "src/painter.hpp"

namespace scantrace::grade {
namespace {

// A pixel that holds the index of the face being filled. The fill converts colours to pixels with
// P::from(Color); this pixel ignores the colour and takes the current face, which the render loop
// below sets before each face (one thread, one render at a time: thread_local).
struct FaceId {
  int id = -1;
  static thread_local int current;
  static FaceId from(Color) { return {current}; }
};
thread_local int FaceId::current = -1;

}  // namespace

FaceIdImage render_face_ids(const Scene& scene, const FillOptions& options) {
  Image<FaceId> image(scene.width, scene.height, FaceId{-1});
  const std::vector<double> depth = face_depths(scene);
  // The colours do not matter; flat shading keeps the fill to one conversion per face.
  FillOptions opt = options;
  opt.shading = Shading::flat;
  FillScratch scratch;
  const auto fill = [&](auto& canvas, int f) {
    const auto& face = scene.faces[f];
    const std::array<Vec2, 3> v{scene.vertices[face[0]], scene.vertices[face[1]],
                                scene.vertices[face[2]]};
    const std::array<Color, 3> c{scene.vcolors[face[0]], scene.vcolors[face[1]],
                                 scene.vcolors[face[2]]};
    FaceId::current = f;
    fill_polygon(canvas, PolygonInput{v, c, f, depth[f]}, opt, scratch);
  };
  if (options.visibility == Visibility::zbuffer) {
    ZBufferCanvas<FaceId> canvas(image);
    const SubpixelGrid grid(opt.subpixel_bits);
    for (int f = 0; f < static_cast<int>(scene.faces.size()); ++f) {
      const auto& face = scene.faces[f];
      const std::array<Vec2, 3> v{scene.vertices[face[0]], scene.vertices[face[1]],
                                  scene.vertices[face[2]]};
      const std::array<double, 3> d{scene.depth[face[0]], scene.depth[face[1]],
                                    scene.depth[face[2]]};
      if (grid.valid()) canvas.begin_triangle(v, d, grid);
      fill(canvas, f);
    }
  } else {
    ImageCanvas<FaceId> canvas(image);
    for (int f : painter_order(depth)) fill(canvas, f);
  }
  FaceIdImage out{scene.width, scene.height, {}};
  out.ids.reserve(static_cast<std::size_t>(scene.width) * scene.height);
  for (const FaceId p : image.pixels()) out.ids.push_back(p.id);
  return out;
}

}  // namespace scantrace::grade
