#include "cli/model_flags.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "cli/canvas_size.hpp"
#include "cli/deprecated_option.hpp"
#include "cli/option_choice.hpp"
#include "cli/trace_flags.hpp"
#include "cli/validators.hpp"
#include "io/obj_loader.hpp"

namespace scantrace::cli {

Vec3 parse_vec3(const std::string& text, const std::string& what) {
  std::vector<double> v;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ',');) {
    double x = 0;
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), x);
    if (part.empty() || ec != std::errc() || end != part.data() + part.size() || !std::isfinite(x))
      throw std::invalid_argument(what + ": \"" + part + "\" is not a finite number");
    v.push_back(x);
  }
  if (v.size() != 3) throw std::invalid_argument(what + ": \"" + text + "\" is not X,Y,Z");
  return {v[0], v[1], v[2]};
}

FillOptions ModelFlags::apply(FillOptions o, bool model) const {
  // A model is culled and z-buffered; a scene keeps the course's render (the tables' defaults).
  o.cull =
      cull.empty() ? (model ? Cull::back : option_table<Cull>().default_value) : chosen<Cull>(cull);
  o.visibility = depth.empty()
                     ? (model ? Visibility::zbuffer : option_table<Visibility>().default_value)
                     : chosen<Visibility>(depth);
  return o;
}

Scene ModelFlags::load_model(const std::string& file, Shading shading) const {
  std::vector<std::string> warnings;
  const Mesh mesh = load_obj(file, &warnings);
  for (const std::string& w : warnings) spdlog::warn("warning: {}", w);
  ShadeOptions o;
  o.colors = colors == "random"  ? ColorSource::random
             : colors == "white" ? ColorSource::white
                                 : ColorSource::file;
  o.seed = seed;
  o.light.enabled = !unlit;
  o.light.direction = parse_vec3(light, "--light");
  o.light.ambient = ambient;
  o.shading = shading;
  o.gamma = gamma;
  std::tie(o.camera.width, o.camera.height) =
      canvas_size_or(size, kDefaultCanvasSize, kDefaultCanvasSize);
  const Vec3 bg = parse_vec3(background, "--background");
  o.background = {bg.x, bg.y, bg.z};
  if (!eye.empty()) {
    o.camera.perspective = true;
    o.camera.eye = parse_vec3(eye, "--eye");
    if (!target.empty()) o.camera.target = parse_vec3(target, "--target");
    o.camera.fov_degrees = fov;
  }
  ShadeStats stats;
  Scene scene;
  try {
    scene = shade_mesh(mesh, o, &stats);
  } catch (const std::invalid_argument& e) {
    throw InputError(file, "camera", e.what());
  }
  if (stats.faces_behind_eye > 0)
    spdlog::warn("warning: {}: {} faces have a vertex behind the eye and are not drawn", file,
                 stats.faces_behind_eye);
  return scene;
}

std::variant<Scene, trace::TriangleInput, trace::GeneralPolygonInput> trace_input(
    const TraceFlags& what, const ModelFlags& model, Shading shading, bool clamp_colors) {
  if (!what.scene.empty() && is_obj_file(what.scene)) {
    // One canvas option: trace's --size (the deprecated --model-size when --size is absent).
    ModelFlags m = model;
    if (!what.size.empty()) m.size = what.size;
    return m.load_model(what.scene, shading);
  }
  return what.input(clamp_colors);
}

void add_model_flags(CLI::App& cmd, ModelFlags& f, bool beside_triangle_flags) {
  // One name per meaning on every command: --model-colors is the model's base colour (--colors
  // are the vertex colours of --triangle/--polygon), --size the canvas (cli/canvas_size.hpp).
  const auto vec3 = [](const char* what) {
    return parsed_by([what](const std::string& v) { parse_vec3(v, what); });
  };
  const std::string g = "Models (.obj)";
  cmd.add_option("--light", f.light,
                 "direction the light travels, X,Y,Z (0,0,-1: from the\n"
                 "viewer into the screen); Lambert: ambient + (1-ambient)\n"
                 "* max(0, n . -light)")
      ->check(vec3("--light"))
      ->capture_default_str()
      ->group(g);
  cmd.add_flag("--unlit", f.unlit, "no lighting: the base colours as they are")->group(g);
  cmd.add_option("--ambient", f.ambient, "light every face receives, in [0, 1]")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str()
      ->group(g);
  cmd.add_option("--gamma", f.gamma,
                 "encode the shaded vertex colours as c^(1/G)\n"
                 "(2.2 for a display; 1 = off)")
      ->check(CLI::Range(0.1, 10.0))
      ->capture_default_str()
      ->group(g);
  cmd.add_option("--model-colors", f.colors,
                 "base colour: file (the model's vertex colours, white\n"
                 "without), random (one per face, from --seed), white")
      ->check(CLI::IsMember({"file", "random", "white"}))
      ->capture_default_str()
      ->group(g);
  cmd.add_option("--seed", f.seed, "seed of --model-colors random")
      ->capture_default_str()
      ->group(g);
  auto* eye = cmd.add_option("--eye", f.eye,
                             "perspective camera at X,Y,Z (default: orthographic,\n"
                             "looking down -z, the model fitted to the canvas)")
                  ->check(vec3("--eye"))
                  ->group(g);
  cmd.add_option("--target", f.target, "point the camera looks at (default: model centre)")
      ->check(vec3("--target"))
      ->needs(eye)
      ->group(g);
  cmd.add_option("--fov", f.fov, "vertical field of view in degrees")
      ->check(CLI::Range(1.0, 179.0))
      ->needs(eye)
      ->capture_default_str()
      ->group(g);
  if (beside_triangle_flags) {
    // trace and explain own --size (add_trace_flags); this was the model's name for it there.
    add_deprecated_alias(cmd, "--model-size", "--size", f.size)->check(parsed_by(parse_size));
  } else {
    add_canvas_size_option(cmd, f.size);
    // The model's old name for the canvas works here as on trace, explain and step, so one spelling works everywhere.
    add_deprecated_alias(cmd, "--model-size", "--size", f.size)->check(parsed_by(parse_size));
    // render spelled the model's colours --colors before they had one name everywhere.
    add_deprecated_alias(cmd, "--colors", "--model-colors", f.colors)
        ->check(CLI::IsMember({"file", "random", "white"}));
  }
  cmd.add_option("--background", f.background, "canvas colour of a model, R,G,B in [0, 1]")
      ->check(parsed_by([](const std::string& v) {
        const Vec3 c = parse_vec3(v, "--background");
        for (double x : {c.x, c.y, c.z})
          if (x < 0 || x > 1) throw std::invalid_argument("--background: components in [0, 1]");
      }))
      ->capture_default_str()
      ->group(g);
  add_choice<Cull>(cmd, "--cull", f.cull)->group(g);
  add_choice<Visibility>(cmd, "--depth", f.depth)->group(g);
}

}  // namespace scantrace::cli
