#include "cli/grade_scene.hpp"

#include "cli/canvas_size.hpp"
#include "cli/scene_input.hpp"
#include "io/obj_loader.hpp"

namespace scantrace::cli {

GradeScene load_grade_scene(const std::string& file, const FillFlags& fill,
                            const ModelFlags& model) {
  const bool obj = is_obj_file(file);
  GradeScene g;
  g.options = model.apply(fill.options(), obj);
  g.scene =
      obj ? model.load_model(file, g.options.shading) : load_scene_file(file, fill.clamp_colors);
  // --size is the canvas on every command that takes a scene: for a scene file it overrides the
  // file's (a model is fitted to it by load_model already).
  if (!obj) apply_canvas_size(g.scene, model.size);
  return g;
}

}  // namespace scantrace::cli
