// scantrace demo [-o DIR]: the embedded default, no input needed. Renders the built-in demo scene
// both ways, fills the course's example triangle, traces it and replays the trace into the
// explanatory video and page (cli/demo_explain.hpp), and saves the scene so that `scantrace
// render` can reproduce the renders from a file. Compiled into both executables: `scantrace`
// runs it when scantrace-tools is not built (the demo's build, cli/main_render.cpp).
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/demo_explain.hpp"
#include "cli/stopwatch.hpp"
#include "demo/demo_mesh.hpp"
#include "demo/demo_scene.hpp"
#include "io/png_writer.hpp"
#include "io/scene_json.hpp"
#include "src/painter.hpp"
#include "src/shade_mesh.hpp"
#include "trace/record.hpp"

namespace scantrace::cli {
namespace {

struct DemoArgs {
  std::string dir = "scantrace-demo";
};

void make_output_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error(dir.string() + ": cannot create directory: " + ec.message());
}

void render_scene(const Scene& scene, Shading shading, const std::filesystem::path& file) {
  FillOptions options;
  options.shading = shading;
  RenderStats stats;
  const Stopwatch clock;
  const RgbImage image = render(scene, options, &stats);
  const double ms = clock.ms();
  png::write(image, file);
  spdlog::info(
      "wrote {}: the demo scene, {} shading ({} faces drawn, {} skipped, {} pixels, "
      "{:.2f} ms)",
      file.string(), to_string(shading), stats.triangles_filled, stats.triangles_skipped,
      stats.pixels, ms);
}

// The generated torus, lit and Gouraud-shaded through a z-buffer with back faces culled: what
// `scantrace render MODEL.obj` does to a file, on a mesh that needs none.
void render_model(const std::filesystem::path& file) {
  ShadeOptions shade;
  shade.light.direction = {-1, -1, -1.5};
  shade.gamma = 2.2;
  const Scene scene = shade_mesh(demo_torus(), shade);
  FillOptions options;
  options.cull = Cull::back;
  options.visibility = Visibility::zbuffer;
  RenderStats stats;
  const RgbImage image = render(scene, options, &stats);
  png::write(image, file);
  spdlog::info(
      "wrote {}: a generated torus ({} faces), Lambert-lit, Gouraud, gamma 2.2, z-buffer "
      "({} drawn, {} culled as back faces)",
      file.string(), scene.faces.size(), stats.triangles_filled, stats.triangles_culled);
}

// The course's example triangle, filled once under a scanline-level tracer: the PNG and the trace
// come from the same fill, so the narration is of exactly the pixels in the image.
void trace_demo_triangle(const std::filesystem::path& image_file,
                         const std::filesystem::path& trace_file) {
  const DemoTriangle t;
  trace::TriangleInput input;
  input.vertices = t.vertices;
  input.colors = t.colors;
  RgbImage image;
  const trace::Footer footer =
      trace::write_triangle_trace(trace_file, input, FillOptions{}, trace::TraceFilter{}, &image);
  png::write(image, image_file);
  spdlog::info(
      "wrote {}: the course's example triangle (20,20) (250,80) (300,400), red, green "
      "and blue vertices, Gouraud",
      image_file.string());
  spdlog::info("wrote {}: its step-by-step trace, {} events (edge table, then every scanline)",
               trace_file.string(), footer.events);
}

void run_demo(const DemoArgs& args, ExplainDemo explain) {
  const std::filesystem::path dir = args.dir;
  make_output_directory(dir);
  const Scene scene = demo_scene();
  render_scene(scene, Shading::flat, dir / "demo_flat.png");
  render_scene(scene, Shading::gouraud, dir / "demo_gouraud.png");
  render_model(dir / "demo_model.png");
  trace_demo_triangle(dir / "triangle_gouraud.png", dir / "triangle.jsonl");
  explain(dir / "triangle.jsonl", dir / "triangle.mp4", dir / "triangle.html");
  const std::filesystem::path scene_file = dir / "demo_scene.json";
  save_scene(scene, scene_file);
  spdlog::info(
      "wrote {}: the demo scene as a scene file ({} vertices, {} faces); re-render it "
      "with: scantrace render {}",
      scene_file.string(), scene.vertices.size(), scene.faces.size(), scene_file.string());
}

}  // namespace

Command add_demo_command(CLI::App& app, ExplainDemo explain) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* cmd = app.add_subcommand("demo",
                                     "The embedded default, no input needed: renders the\n"
                                     "built-in demo scene (a mesh of triangles sharing edges,\n"
                                     "a sun of thin triangles, three overlapping triangles at\n"
                                     "different depths) flat and Gouraud, fills the course's\n"
                                     "example triangle, traces it and turns the trace into an\n"
                                     "explanatory video and page, and saves the scene as a\n"
                                     "scene file.");
  cmd->add_option("-o,--output", args->dir, "directory to write into (created if missing)")
      ->capture_default_str();
  cmd->footer(
      "Writes DIR/demo_flat.png, DIR/demo_gouraud.png, DIR/demo_model.png (a lit,\n"
      "Gouraud-shaded torus), DIR/triangle_gouraud.png\n"
      "(512x512 each), DIR/triangle.jsonl (its trace), DIR/triangle.mp4 (the video\n"
      "of that trace, 1280x720, under a minute), DIR/triangle.html (the same\n"
      "steps as a page to step through in a browser) and DIR/demo_scene.json.\n"
      "The demo's own build (scripts/build.sh --demo, without OpenCV) writes the\n"
      "page with SVG frames and no video; the full build adds the video, and its\n"
      "page holds the trace and the WebAssembly player when the web build is there.");
  return {cmd, [args, explain] { run_demo(*args, explain); }};
}

}  // namespace scantrace::cli
