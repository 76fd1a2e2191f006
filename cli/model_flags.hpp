#pragma once
// The options of an OBJ model (render, trace and explain take a .obj wherever they take a scene
// file), and the two visibility options that apply to scenes too:
//   --light X,Y,Z  --unlit  --ambient A  --gamma G  --model-colors file|random|white  --seed N
//   --eye X,Y,Z [--target X,Y,Z] [--fov DEG] (perspective; orthographic fit otherwise)
//   --size WxH  --cull none|back|front  --depth painter|zbuffer
// Defaults differ by input: a model is culled (back) and z-buffered, a course scene keeps the
// course's painter's order without culling.
#include <string>
#include <variant>

#include "cli/trace_flags.hpp"

#include "src/fill_options.hpp"
#include "src/scene.hpp"
#include "src/shade_mesh.hpp"

namespace CLI {
class App;
}

namespace scantrace::cli {

struct ModelFlags {
  std::string light = "0,0,-1";
  bool unlit = false;
  double ambient = 0.1;
  double gamma = 1.0;
  std::string colors = "file";
  unsigned long long seed = 1;
  std::string eye, target;
  double fov = 45;
  std::string size;  // the canvas (cli/canvas_size.hpp); empty: 512x512
  std::string background = "1,1,1";
  std::string cull;   // empty: by input
  std::string depth;  // empty: by input

  // `base` with --cull and --depth applied (or the defaults for a model / a scene).
  FillOptions apply(FillOptions base, bool model) const;
  // Loads the OBJ `file` and shades it into a scene (InputError for a bad file); tinyobjloader's
  // warnings and faces omitted behind the eye are logged.
  Scene load_model(const std::string& file, Shading shading) const;
};

// `beside_triangle_flags`: the command also has trace's flags, which own --size (trace, explain;
// --model-size stays as a deprecated alias there); otherwise --size is added here (render), with
// --model-size and render's old --colors (of --model-colors) as deprecated aliases.
void add_model_flags(CLI::App& command, ModelFlags& flags, bool beside_triangle_flags);

// What trace and explain fill: a model shaded into a scene, a scene file, or one triangle.
std::variant<Scene, trace::TriangleInput, trace::GeneralPolygonInput> trace_input(
    const TraceFlags& what, const ModelFlags& model, Shading shading, bool clamp_colors);

// "x,y,z" → a vector (throws std::invalid_argument naming `what`).
Vec3 parse_vec3(const std::string& text, const std::string& what);

}  // namespace scantrace::cli
