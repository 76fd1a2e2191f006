// scantrace render SCENE [--shading …] [--fill-rule …] [--subpixel-bits N] [--method …]
//                        [-o OUT.png]
#include <filesystem>
#include <memory>
#include <string>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "cli/canvas_size.hpp"
#include "cli/commands.hpp"
#include "cli/fill_flags.hpp"
#include "cli/model_flags.hpp"
#include "cli/scene_input.hpp"
#include "cli/stopwatch.hpp"
#include "io/interrupt.hpp"
#include "io/obj_loader.hpp"
#include "io/png_writer.hpp"
#include "io/scene_json.hpp"
#include "src/band_render.hpp"
#include "src/face_skips.hpp"
#include "src/painter.hpp"

namespace scantrace::cli {
namespace {

struct RenderArgs {
  std::string scene;
  std::string output;  // empty: SCENE's stem + ".png" in the current directory
  FillFlags fill;
  ModelFlags model;
  int threads = 1;
  bool near_to_far = false;  // --occlusion
  bool far_to_near = false;  // --no-occlusion
};

std::filesystem::path output_path(const RenderArgs& args) {
  if (!args.output.empty()) return args.output;
  return std::filesystem::path(args.scene).stem().string() + ".png";
}

void run_render(const RenderArgs& args) {
  const std::filesystem::path out = output_path(args);
  const Stopwatch load_clock;
  const bool model = is_obj_file(args.scene);
  FillOptions options = args.model.apply(args.fill.options(), model);
  if (args.near_to_far) options.occlusion = Occlusion::near_to_far;
  if (args.far_to_near) options.occlusion = Occlusion::far_to_near;
  Scene scene = model ? args.model.load_model(args.scene, options.shading)
                      : load_scene_file(args.scene, args.fill.clamp_colors);
  if (!model) apply_canvas_size(scene, args.model.size);  // --size overrides the file's canvas
  const double load_ms = load_clock.ms();
  // Ctrl-C while the scene loaded stops here; the render itself does not look at the flag (a
  // second Ctrl-C ends it at once) and the PNG's write refuses to commit after one.
  check_interrupt();

  RenderStats stats;
  const Stopwatch render_clock;
  // Bands of rows on several threads draw exactly the single-threaded image (band_render.hpp).
  const RgbImage image = args.threads == 1
                             ? render(scene, options, &stats)
                             : render_parallel<Rgb32f>(scene, options, args.threads, &stats);
  const double render_ms = render_clock.ms();
  png::write(image, out);
  // A hint given after the write succeeded, so that a failing run prints only its error line.
  if (out.extension() != ".png" && out.extension() != ".PNG")
    spdlog::warn("warning: {}: the name does not end in .png; writing PNG data anyway",
                 out.string());
  // Nothing below is printed under --quiet: no work for it either.
  if (!spdlog::should_log(spdlog::level::info)) return;
  // The report's face counts, the same whichever way the render ran (src/face_skips.hpp): a pass
  // over the faces after the timed render.
  count_skips_by_geometry(scene, options, stats);
  // One line, as every command's report: near to far adds what it did not draw. A face rejected
  // from its box may also be one the set-up would skip, so the rejections are not a part of the
  // hidden faces but a count of their own.
  const bool near_to_far = stats.path == Occlusion::near_to_far;
  const std::string skipped_hidden =
      near_to_far ? fmt::format(
                        ", {} hidden under nearer faces; {} faces rejected from their box "
                        "before set-up",
                        stats.triangles_hidden, stats.triangles_rejected)
                  : "";
  // The header names the way the faces were drawn: the painter's far to near, or near to far.
  const std::string visibility =
      std::string(to_string(options.visibility)) + (near_to_far ? " near to far" : "");
  // (Z-buffered, pixels are counted before their depth test: not each written once.)
  const std::string writes =
      stats.path == Occlusion::near_to_far && options.visibility == Visibility::painter
          ? fmt::format(" written once each, near to far ({} pixel writes clipped)",
                        stats.pixels_clipped)
          : "";
  spdlog::info(
      "rendered {} ({}x{}, {}, {}, {}, {}, cull {}): {} faces drawn, {} culled, {} skipped{}{}, {} "
      "pixels{} in {:.2f} ms (load {:.1f} ms) -> {}",
      args.scene, scene.width, scene.height, to_string(options.shading),
      to_string(options.fill_rule), to_string(options.method), visibility, to_string(options.cull),
      stats.triangles_filled, stats.triangles_culled, stats.triangles_skipped,
      // Why a face draws nothing (SkipReason): said whenever some did.
      stats.triangles_skipped > 0
          ? " (zero area after snapping, no pixel centre inside, or off the canvas)"
          : "",
      skipped_hidden, stats.pixels, writes, render_ms, load_ms, out.string());
}

}  // namespace

Command add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render",
                                     "Renders a scene file to a PNG: every face filled by the\n"
                                     "exact edge-table scanline fill, farthest first (painter's\n"
                                     "order). Prints faces drawn/skipped, pixels and time.");
  cmd->add_option("SCENE", args->scene,
                  "scene file: JSON with vertices, vcolors, faces, depth\n"
                  "and optional width, height, background; a MATLAB .mat\n"
                  "scene (vertices_2d, faces 1-based, vertex_colors, depth;\n"
                  "canvas 512x512); or an OBJ model (.obj), lit and\n"
                  "projected (see Models)")
      ->required();
  cmd->add_option("-o,--output", args->output,
                  "output PNG (default: SCENE's name with .png, in the\n"
                  "current directory)");
  add_fill_flags(*cmd, args->fill);
  add_model_flags(*cmd, args->model, false);
  cmd->add_option("--threads", args->threads,
                  "threads drawing horizontal bands of the image (0: one per\n"
                  "core), painter's or z-buffered; the image is bit-identical\n"
                  "to the one-thread render (--method float runs on one\n"
                  "thread: its x and colours accumulate down each edge)")
      ->check(CLI::Range(0, 256))
      ->capture_default_str();
  CLI::Option* near = cmd->add_flag("--occlusion", args->near_to_far,
                                    "draw near to far, whatever the scene: the painter's order\n"
                                    "reversed, each pixel written once by the face the painter\n"
                                    "leaves on it, faces whose box is already covered skipped\n"
                                    "before their set-up, the background last. With --depth\n"
                                    "zbuffer: faces in that order, an exact depth tie still going\n"
                                    "to the face first in the scene, faces whose box is all\n"
                                    "nearer skipped before their set-up (one thread; bands keep\n"
                                    "scene order). The same image, bit for bit. Without this flag\n"
                                    "or --no-occlusion the way is chosen per scene: near to far\n"
                                    "when the faces form surfaces (they share vertices) stacked\n"
                                    "2.0 deep or more flat, 1.6 Gouraud, as the course scene's\n"
                                    "are (about as fast flat, 0.71 of the time Gouraud);\n"
                                    "z-buffered, also only up to 512x512\n"
                                    "(docs/performance.md). The report line says when near to\n"
                                    "far ran");
  cmd->add_flag("--no-occlusion", args->far_to_near,
                "draw far to near, whatever the scene: every face painted\n"
                "over the farther ones, as the course teaches (z-buffered:\n"
                "in scene order); to compare with --occlusion")
      ->excludes(near);
  cmd->footer(
      "Examples:\n"
      "  scantrace render scene.json                     writes ./scene.png\n"
      "  scantrace render scene.json --shading flat -o flat.png\n"
      "  scantrace render scene.json --fill-rule closed --subpixel-bits 0\n"
      "  scantrace render scene.json --method float      the textbook loop, for comparison\n"
      "  scantrace render head.obj --light 0,0,-1 --shading gouraud --cull back --gamma 2.2\n"
      "      --depth zbuffer -o head.png");
  return {cmd, [args] { run_render(*args); }};
}

}  // namespace scantrace::cli
