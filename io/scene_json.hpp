#pragma once
// The scene file: a JSON object with the course's keys (docs/design.md §2, README "Scene files")
//
//   vertices    L×2  [x, y] pixels, x = column, y = row (pointing down)
//   vcolors     L×3  [r, g, b] in [0, 1]
//   faces       K×3  0-based vertex indices
//   depth       L    one number per vertex (larger = farther)
//   width, height    optional integers, default 512
//   background       optional [r, g, b], default white
//
// Other keys are ignored. Every problem is reported as an InputError naming the file and the
// element, e.g. "scene.json: faces[812]: vertex index 5012 is out of range (4999 vertices)" or,
// for malformed JSON, "scene.json:3:17: JSON syntax error: ...".
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>

#include "io/input_error.hpp"
#include "src/scene.hpp"

namespace scantrace {

// What --clamp-colors did: how many colours (vcolors entries and the background) had a component
// outside [0, 1] and were clamped into it, and the first of them ("vcolors[3]").
struct ColorClamping {
  std::size_t clamped = 0;
  std::string first;
};

// Reads, parses and validates a scene file. Colours outside [0, 1] are an error naming the
// element, unless `clamping` is given: then they are clamped and counted in it.
Scene load_scene(const std::filesystem::path& file, ColorClamping* clamping = nullptr);

// Parses and validates a scene from a stream; `name_for_errors` starts every error message.
Scene parse_scene(std::istream& in, const std::string& name_for_errors,
                  ColorClamping* clamping = nullptr);
Scene parse_scene_text(std::string_view text, const std::string& name_for_errors,
                       ColorClamping* clamping = nullptr);

// The scene as JSON text with every key present, one array element per line (so that a syntax
// error's line number points at the element). Doubles are written with enough digits to read
// back bit for bit.
std::string scene_to_json(const Scene& scene);

// Writes scene_to_json(scene) to `file`, atomically (io/atomic_write.hpp).
void save_scene(const Scene& scene, const std::filesystem::path& file);

}  // namespace scantrace
