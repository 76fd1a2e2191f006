#include "cli/canvas_size.hpp"

#include <CLI/CLI.hpp>

#include "cli/scene_input.hpp"
#include "cli/trace_flags.hpp"
#include "cli/validators.hpp"

namespace scantrace::cli {

CLI::Option* add_canvas_size_option(CLI::App& command, std::string& size) {
  return command
      .add_option("--size", size,
                  "canvas WIDTHxHEIGHT: of --triangle, --polygon or a model\n"
                  "(default 512x512); for a scene file it overrides the\n"
                  "file's width and height")
      ->check(parsed_by(parse_size));
}

std::pair<int, int> canvas_size_or(const std::string& size, int fallback_w, int fallback_h) {
  if (size.empty()) return {fallback_w, fallback_h};
  return parse_size(size);
}

void apply_canvas_size(Scene& scene, const std::string& size) {
  if (size.empty()) return;
  std::tie(scene.width, scene.height) = parse_size(size);
  check_canvas_memory(scene.width, scene.height, "--size", size);
}

}  // namespace scantrace::cli
