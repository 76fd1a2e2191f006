// scantrace demo [-o DIR]: the embedded default, no input needed. Renders the built-in demo scene
// both ways, fills the course's example triangle, traces it and replays the trace into the
// explanatory video, and saves the scene so that `scantrace render` can reproduce the renders
// from a file.
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/stopwatch.hpp"
#include "cli/trace_page.hpp"
#include "demo/demo_mesh.hpp"
#include "demo/demo_scene.hpp"
#include "io/scene_json.hpp"
#include "src/painter.hpp"
#include "src/shade_mesh.hpp"
#include "trace/record.hpp"
#include "viz/image_file.hpp"
#include "viz/progress.hpp"
#include "viz/replay.hpp"

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
  write_png(image, file);
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
  write_png(image, file);
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
  write_png(image, image_file);
  spdlog::info(
      "wrote {}: the course's example triangle (20,20) (250,80) (300,400), red, green "
      "and blue vertices, Gouraud",
      image_file.string());
  spdlog::info("wrote {}: its step-by-step trace, {} events (edge table, then every scanline)",
               trace_file.string(), footer.events);
}

// The video and the page are made from the trace file just written, so they explain exactly what
// the file holds; it is read once for both.
void explain_demo_triangle(const std::filesystem::path& trace_file,
                           const std::filesystem::path& video, const std::filesystem::path& page) {
  const trace::Trace t = trace::Trace::load(trace_file);
  viz::ReplayOptions options;
  options.source = trace_file.string();
  const auto replay_to = [&](const std::filesystem::path& out) {
    std::unique_ptr<viz::Progress> progress;
    if (spdlog::should_log(spdlog::level::info))
      progress = std::make_unique<viz::StderrProgress>(out.string(), "frames");
    return viz::replay(t, out, options, progress.get());
  };
  const Stopwatch clock;
  const viz::ReplayResult r = replay_to(video);
  spdlog::info(
      "wrote {}: the explanatory video of that trace, {} steps, {:.0f} s ({} {}x{}, {} "
      "frames, made in {:.1f} s)",
      video.string(), r.steps, r.seconds, r.format == "h264" ? "H.264" : "MPEG-4",
      options.size.width, options.size.height, r.frames, clock.ms() / 1000);
  // The trace and its player when the web build is there (cli/trace_page.hpp); the demo's own
  // build has none, and writes the page of pre-drawn frames.
  if (!trace_page_template().empty()) {
    const std::size_t bytes = write_trace_page(t, options, page);
    spdlog::info(
        "wrote {}: the same steps as a self-contained page (the trace and its player, {:.0f} KB): "
        "open it in a browser and step with the arrow keys",
        page.string(), bytes / 1e3);
    return;
  }
  // Without the web build (the demo's own build leaves out emscripten, minutes of compiling): the
  // page of pre-drawn frames, and the line says how to get the small one.
  const viz::ReplayResult p = replay_to(page);
  spdlog::info(
      "wrote {}: the same steps as a self-contained page ({} steps, {:.1f} MB of pre-drawn "
      "frames: this build has no web build; `bash scripts/build.sh --web`, then `scantrace replay "
      "{} -o {}`, writes the trace page of under 1 MB): open it in a browser and step with the "
      "arrow keys",
      page.string(), p.steps, p.bytes / 1e6, trace_file.string(), page.string());
}

void run_demo(const DemoArgs& args) {
  const std::filesystem::path dir = args.dir;
  make_output_directory(dir);
  const Scene scene = demo_scene();
  render_scene(scene, Shading::flat, dir / "demo_flat.png");
  render_scene(scene, Shading::gouraud, dir / "demo_gouraud.png");
  render_model(dir / "demo_model.png");
  trace_demo_triangle(dir / "triangle_gouraud.png", dir / "triangle.jsonl");
  explain_demo_triangle(dir / "triangle.jsonl", dir / "triangle.mp4", dir / "triangle.html");
  const std::filesystem::path scene_file = dir / "demo_scene.json";
  save_scene(scene, scene_file);
  spdlog::info(
      "wrote {}: the demo scene as a scene file ({} vertices, {} faces); re-render it "
      "with: scantrace render {}",
      scene_file.string(), scene.vertices.size(), scene.faces.size(), scene_file.string());
}

}  // namespace

Command add_demo_command(CLI::App& app) {
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
      "steps as a page to step through in a browser) and DIR/demo_scene.json.");
  return {cmd, [args] { run_demo(*args); }};
}

}  // namespace scantrace::cli
