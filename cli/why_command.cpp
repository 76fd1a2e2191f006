// scantrace why SCENE X Y [fill options] [model options] [--json] [--explain OUT]
// The history of one pixel in the algorithm's terms (grade/pixel_story.hpp).
#include <charconv>
#include <cstdio>
#include <stdexcept>
#include <ctime>
#include <memory>
#include <string>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/grade_scene.hpp"
#include "cli/replay_flags.hpp"
#include "cli/stopwatch.hpp"
#include "cli/validators.hpp"
#include "grade/pixel_story.hpp"
#include "grade/scene_around.hpp"
#include "io/memory_budget.hpp"
#include "trace/record.hpp"

namespace scantrace::cli {
namespace {

// The faces --explain replays at most: each is a frame per row of it.
constexpr std::size_t kMaxExplainedFaces = 100;

struct WhyArgs {
  std::string scene;
  int x = 0, y = 0;
  FillFlags fill;
  ModelFlags model;
  bool json = false;
  std::string explain;
};

void run_why(const WhyArgs& args) {
  const GradeScene g = load_grade_scene(args.scene, args.fill, args.model);
  if (args.x >= g.scene.width || args.y >= g.scene.height)
    throw InputError(args.scene, "X Y",
                     "pixel (" + std::to_string(args.x) + ", " + std::to_string(args.y) +
                         ") is outside the " + std::to_string(g.scene.width) + "x" +
                         std::to_string(g.scene.height) + " canvas");
  // The memory why() takes is linear in the faces around the pixel: refused up front past the
  // budget, in the usual one line.
  const std::size_t around =
      grade::faces_around(g.scene, args.x, args.y, grade::snap_margin(g.options)).size();
  check_memory(static_cast<std::uint64_t>(around) * grade::kWhyBytesPerFace,
               "explaining pixel (" + std::to_string(args.x) + ", " + std::to_string(args.y) +
                   ") through the " + std::to_string(around) + " faces around it",
               args.scene, "X Y");
  const Stopwatch clock;
  const std::clock_t cpu = std::clock();
  const grade::PixelStory story = grade::why(g.scene, g.options, args.x, args.y);
  const double ms = clock.ms();
  const double cpu_ms = 1000.0 * static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
  const std::string out = args.json ? story.to_json().dump(2) + "\n" : story.to_text();
  std::fwrite(out.data(), 1, out.size(), stdout);
  std::fflush(stdout);
  spdlog::info(
      "answered in {:.2f} ms, {:.2f} ms of CPU, after loading ({} faces around the pixel, "
      "{} in the scene)",
      ms, cpu_ms, story.faces.size(), g.scene.faces.size());
  if (!args.explain.empty()) {
    // Only the faces around the pixel, every row of them, named by their scene index: the replay
    // shows how each one was filled, with the pixel ringed on every frame. Every row of 10k faces
    // took over a minute and 1.75 GB: past kMaxExplainedFaces, the last ones drawn are shown
    // (the pixel's final colour is theirs), and a warning says how many were left out.
    std::vector<int> shown;
    for (const grade::FaceStep& s : story.faces) shown.push_back(s.face);
    if (shown.size() > kMaxExplainedFaces) {
      spdlog::warn("warning: --explain shows the last {} of the {} faces around the pixel, in "
                   "drawing order (the earlier ones are in the text above)",
                   kMaxExplainedFaces, shown.size());
      shown.erase(shown.begin(), shown.end() - static_cast<std::ptrdiff_t>(kMaxExplainedFaces));
    }
    trace::TraceFilter filter;
    filter.level = TraceLevel::scanline;
    filter.triangles = trace::IndexSet::of(shown);
    const trace::Trace t = trace::record_scene(g.scene, g.options, filter);
    ReplayFlags replay;
    replay.output = args.explain;
    replay.marked_pixel = viz::CanvasPixel{args.x, args.y};
    run_replay(t, replay,
               "the faces around pixel (" + std::to_string(args.x) + ", " + std::to_string(args.y) +
                   ") of " + args.scene);
  }
}

// X and Y said as what they are: CLI11's NonNegativeNumber answered "abc" with "Value abc not in
// range 0.000000 to 1797693134862315708145274237317043567980...", 379 characters.
CLI::Validator pixel_coordinate(const char* what, const char* side) {
  return parsed_by([what, side](const std::string& v) {
    int value = 0;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), value);
    if (v.empty() || ec != std::errc() || end != v.data() + v.size() || value < 0)
      throw std::invalid_argument(std::string("must be a pixel ") + what + ", 0 to the canvas " +
                                  side + " - 1 (got \"" + v + "\")");
  });
}

}  // namespace

Command add_why_command(CLI::App& app) {
  auto args = std::make_shared<WhyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "why",
      "Explains why pixel (X, Y) has its colour, in the algorithm's terms: every\n"
      "face whose bounding box holds the pixel centre, in drawing order, and what\n"
      "the fill did about the pixel (skipped and why; row Y outside the face's\n"
      "scanlines; X left or right of the row's span ceil(x_L) .. ceil(x_R) - 1, with\n"
      "the active points; or written, with the colour, t along the span and the\n"
      "depth test), what the fill rule does with a centre exactly on an edge or a\n"
      "vertex, and the final colour. Only the faces around the pixel are traced.");
  cmd->add_option("SCENE", args->scene,
                  "scene file (JSON or MATLAB .mat) or OBJ model, as for\n'render'")
      ->required();
  cmd->add_option("X", args->x, "column of the pixel (0 = left)")
      ->required()
      ->check(pixel_coordinate("column", "width"));
  cmd->add_option("Y", args->y, "row of the pixel (0 = top)")
      ->required()
      ->check(pixel_coordinate("row", "height"));
  add_fill_flags(*cmd, args->fill);
  add_model_flags(*cmd, args->model, false);
  cmd->add_flag("--json", args->json,
                "print one JSON document instead of text (schema:\n"
                "trace/why_schema.json)");
  // Checked while parsing, as replay's -o is: a bad extension is a usage error before the
  // story is printed, not an error after it.
  cmd->add_option("--explain", args->explain,
                  "also replay the faces around the pixel into OUT.mp4,\n"
                  "OUT_DIR/ or OUT.html (as 'replay' writes them)")
      ->check(parsed_by([](const std::string& v) { viz::output_kind(v); }));
  cmd->footer(
      "Examples:\n"
      "  scantrace why scene.json 100 200\n"
      "  scantrace why scene.json 100 200 --json > pixel.json\n"
      "  scantrace why scene.json 100 200 --fill-rule closed --explain pixel.mp4\n"
      "Exit status: 0, 1 bad input (or the pixel is outside the canvas), 2 usage.");
  return {cmd, [args] { run_why(*args); }};
}

}  // namespace scantrace::cli
