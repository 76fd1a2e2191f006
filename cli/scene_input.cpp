#include "cli/scene_input.hpp"

#include <cstdint>

#include <spdlog/spdlog.h>

#include "io/mat_scene.hpp"
#include "io/memory_budget.hpp"
#include "io/scene_json.hpp"

namespace scantrace::cli {

namespace {

// Float RGB canvas (12 bytes), 8-bit BGR image (3) and PNG encoding buffers (about 3), rounded up.
constexpr std::uint64_t kBytesPerPixel = 20;

MatSceneReader mat_reader = nullptr;

// A .mat file is the 2021 course's MATLAB scene (io/mat_scene.hpp), anything else JSON.
Scene load_any(const std::string& file, ColorClamping* clamping) {
  if (is_mat_file(file)) {
    if (mat_reader == nullptr)
      throw InputError(file, "", "MATLAB .mat scenes are read by scantrace-tools, not found here");
    return mat_reader(file, clamping);
  }
  return load_scene(file, clamping);
}

Scene load(const std::string& file, bool clamp_colors) {
  if (!clamp_colors) {
    try {
      return load_any(file, nullptr);
    } catch (const InputError& e) {
      // The one problem an option can fix: say so where the user looks, in the error line.
      if (e.problem().find("outside [0, 1]") == std::string::npos) throw;
      throw InputError(e.file(), e.element(), e.problem() + " (--clamp-colors clamps it)");
    }
  }
  ColorClamping clamping;
  Scene scene = load_any(file, &clamping);
  if (clamping.clamped > 0)
    spdlog::warn("warning: {}: clamped {} colour{} into [0, 1] (--clamp-colors), the first {}",
                 file, clamping.clamped, clamping.clamped == 1 ? "" : "s", clamping.first);
  return scene;
}

}  // namespace

void read_mat_scenes_with(MatSceneReader reader) { mat_reader = reader; }

void check_canvas_memory(int width, int height, const std::string& file,
                         const std::string& element) {
  check_memory(
      static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) * kBytesPerPixel,
      "a " + std::to_string(width) + "x" + std::to_string(height) + " canvas", file, element);
}

Scene load_scene_file(const std::string& file, bool clamp_colors) {
  Scene scene = load(file, clamp_colors);
  check_canvas_memory(scene.width, scene.height, file, "width/height");
  return scene;
}

}  // namespace scantrace::cli
