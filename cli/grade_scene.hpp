#pragma once
// The SCENE of `why` and `diff`, loaded as `render` loads it (scene JSON or OBJ model, with the
// fill and model flags applied), shared by the two grading commands.
#include <string>

#include "cli/fill_flags.hpp"
#include "cli/model_flags.hpp"
#include "src/scene.hpp"

namespace scantrace::cli {

struct GradeScene {
  Scene scene;
  FillOptions options;
};

GradeScene load_grade_scene(const std::string& file, const FillFlags& fill,
                            const ModelFlags& model);

}  // namespace scantrace::cli
