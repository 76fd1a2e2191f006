#include "cli/grade_scene.hpp"

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
  return g;
}

}  // namespace scantrace::cli
