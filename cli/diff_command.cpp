// scantrace diff SCENE IMAGE [fill options] [model options] [--tolerance T] [--no-undo] [-o DIR]
//                [--json]
// Where and why IMAGE differs from the reference render of SCENE (grade/diff_report.hpp).
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <string>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/grade_scene.hpp"
#include "cli/stopwatch.hpp"
#include "cli/validators.hpp"
#include "grade/diff_image.hpp"
#include "grade/diff_report.hpp"
#include "grade/image_input.hpp"
#include "io/atomic_write.hpp"

namespace scantrace::cli {
namespace {

struct DiffArgs {
  std::string scene, image, output;
  FillFlags fill;
  ModelFlags model;
  double tolerance = 1.0 / 255.0;
  bool no_undo = false, json = false;
  grade::JpegBmpDecoder jpeg_bmp = nullptr;
};

void run_diff(const DiffArgs& args) {
  const Stopwatch clock;
  const GradeScene g = load_grade_scene(args.scene, args.fill, args.model);
  const double load_ms = clock.ms();
  const Stopwatch work;
  // CPU time too: on a machine shared with other jobs the wall time says little about the work.
  const std::clock_t cpu = std::clock();
  grade::DiffOptions options;
  options.tolerance = args.tolerance;
  options.undo = !args.no_undo;
  // The image's header first (grade/image_precheck.hpp): a size other than the canvas's is the
  // report at once, nothing decoded.
  const grade::DiffReport report =
      grade::diff_image_file(g.scene, g.options, args.image, args.jpeg_bmp, options);
  const double diff_ms = work.ms();
  const double diff_cpu_ms = 1000.0 * static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
  if (!args.output.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(args.output, ec);
    if (ec)
      throw std::runtime_error(args.output + ": cannot create the directory: " + ec.message());
    const std::filesystem::path dir(args.output);
    // Both or neither (a report.json that is a directory left diff.png behind).
    const std::string png = grade::diff_image_png(report, dir / "diff.png");
    const std::string json = report.to_json().dump(2) + "\n";
    write_files_atomically({{dir / "diff.png", png}, {dir / "report.json", json}});
  }
  const std::string out = args.json ? report.to_json().dump(2) + "\n" : report.to_markdown();
  std::fwrite(out.data(), 1, out.size(), stdout);
  std::fflush(stdout);
  spdlog::info(
      "compared {} with {} in {:.1f} ms, {:.1f} ms of CPU (image decoding included; scene "
      "loaded in {:.1f} ms){}",
      args.image, args.scene, diff_ms, diff_cpu_ms, load_ms,
      // (the path joined, not pasted: `-o graded/` printed graded//diff.png)
      args.output.empty()
          ? ""
          : " -> " + (std::filesystem::path(args.output) / "diff.png").string() + ", report.json");
  if (!report.agrees()) throw ExitStatus{kExitImagesDiffer};
}

}  // namespace

Command add_diff_command(CLI::App& app, grade::JpegBmpDecoder jpeg_bmp) {
  auto args = std::make_shared<DiffArgs>();
  args->jpeg_bmp = jpeg_bmp;
  CLI::App* cmd = app.add_subcommand(
      "diff",
      "Compares IMAGE, what another renderer produced for SCENE, with the reference\n"
      "render, and says where and why they differ: a verdict first, naming the\n"
      "mistakes in the words of the grader's catalogue; the global mistakes (canvas\n"
      "size, background colour, transposed, flipped, BGR, [0, 255] floats), each\n"
      "undone before the pixels are classified (boundary, near_boundary, widened,\n"
      "shifted, order, order_tie, missing_face, degenerate_drawn, colour,\n"
      "background, other;\n"
      "see docs/grading.md). Prints a Markdown summary; -o DIR also writes\n"
      "DIR/diff.png and DIR/report.json.");
  cmd->add_option("SCENE", args->scene,
                  "scene file (JSON or MATLAB .mat) or OBJ model, as for\n'render'")
      ->required();
  cmd->add_option("IMAGE", args->image,
                  "the image to grade: 8-bit PNG, JPEG or BMP, or a NumPy\n"
                  ".npy array HxWx3 (float in [0, 1] or integers 0..255, RGB)")
      ->required();
  add_fill_flags(*cmd, args->fill);
  add_model_flags(*cmd, args->model, false);
  cmd->add_option("--tolerance", args->tolerance,
                  "largest difference per channel (colours in [0, 1]) that\n"
                  "still counts as equal; default 1/255")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_flag("--no-undo", args->no_undo,
                "report global mistakes but classify the pixels as they are");
  cmd->add_option("-o,--output", args->output,
                  "directory for diff.png and report.json (created if needed)")
      ->check(parsed_by([](const std::string& v) {
        if (v.empty()) throw std::invalid_argument("an empty name is not a directory");
      }));
  cmd->add_flag("--json", args->json, "print report.json's content instead of Markdown");
  cmd->footer(
      "Examples:\n"
      "  scantrace diff scene.json student.png\n"
      "  scantrace diff scene.json student.npy --shading flat -o graded/\n"
      "  for f in submissions/*.npy; do scantrace -q diff scene.json \"$f\" --json > \"$f.json\"; "
      "done\n"
      "Exit status: 0 the image agrees within the tolerance, 3 it differs, 1 bad\n"
      "input (one line naming the file and the problem), 2 usage.");
  return {cmd, [args] { run_diff(*args); }};
}

}  // namespace scantrace::cli
