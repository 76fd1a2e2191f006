// scantrace step (TRACE.jsonl | SCENE | --triangle "…" | --polygon "…") [--video-size WxH]
//                [--fps N] [--rows-per-step N] [--mode …] [--step N] [--save-dir DIR]
// Steps through the replay of a trace in an OpenCV HighGUI window, at the user's pace.
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <opencv2/highgui.hpp>

#include "cli/commands.hpp"
#include "cli/fill_flags.hpp"
#include "cli/highgui_focus.hpp"
#include "cli/model_flags.hpp"
#include "cli/record_in_memory.hpp"
#include "cli/replay_flags.hpp"
#include "cli/step_player.hpp"
#include "cli/stopwatch.hpp"
#include "cli/trace_flags.hpp"
#include "cli/trace_input.hpp"
#include "cli/validators.hpp"
#include "cli/x_display.hpp"
#include "io/interrupt.hpp"
#include "io/obj_loader.hpp"
#include "trace/record.hpp"
#include "viz/step_label.hpp"

namespace scantrace::cli {
namespace {

constexpr const char* kWindow = "scantrace step";

struct StepArgs {
  TraceFlags what;
  FillFlags fill;
  ModelFlags model;
  bool partial = false;
  std::string size = "1280x720";
  double fps = 5;
  int rows_per_step = 0;
  std::string mode = "auto";
  std::size_t start = 1;
  std::string save_dir = ".";
};

bool is_trace_file(const std::string& name) {
  return name.size() > 6 && name.compare(name.size() - 6, 6, ".jsonl") == 0;
}

// Throws with one line saying why no window can open, and what to do instead.
void require_display() {
  const std::string instead =
      "; step through a page in a browser instead: scantrace explain ... -o OUT.html or "
      "scantrace replay TRACE.jsonl -o OUT.html";
  const std::string info = cv::getBuildInformation();
  const std::size_t gui = info.find("GUI:");
  if (gui != std::string::npos &&
      info.substr(gui, info.find('\n', gui) - gui).find("NONE") != std::string::npos)
    throw std::runtime_error("this OpenCV has no HighGUI backend to open a window" + instead);
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland))
    throw std::runtime_error("no display to open a window on (DISPLAY is not set)" + instead);
  if (display && *display && (!wayland || !*wayland))
    if (const auto refusal = x_display_refusal(display))
      throw std::runtime_error(std::string("cannot open a window on DISPLAY=") + display + ": " +
                               *refusal + instead);
}

trace::Trace input_trace(const StepArgs& args) {
  if (is_trace_file(args.what.scene)) {
    trace::Trace t = load_trace(args.what.scene, args.partial);
    warn_if_truncated(t, args.what.scene);
    return t;
  }
  return record_in_memory(args.what, args.fill, args.model);
}

struct Clicks {
  std::vector<cv::Point> points;
};

void on_mouse(int event, int x, int y, int /*flags*/, void* data) {
  if (event == cv::EVENT_LBUTTONDOWN) static_cast<Clicks*>(data)->points.emplace_back(x, y);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

void run(const StepArgs& args) {
  const cv::Size size = parse_video_size(args.size);
  // Checked before reading or tracing anything: without a window there is nothing to do.
  require_display();
  const trace::Trace t = input_trace(args);
  viz::StepOptions options;
  options.rows_per_step = args.rows_per_step;
  options.mode = viz::parse_replay_mode(args.mode);
  const std::string source = args.what.scene.empty() ? args.what.input_name() : args.what.scene;
  StepPlayer player(t, options, size, source, args.save_dir);
  player.show(args.start - 1);

  cv::namedWindow(kWindow, cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL);
  Clicks clicks;
  cv::setMouseCallback(kWindow, on_mouse, &clicks);
  keep_keys_with_window();
  std::vector<double> step_ms;  // the time to render and show a step the user moved to
  std::size_t shown = SIZE_MAX;
  std::size_t steps_shown = 0;  // the first step included (it has no move, so no time)
  bool dirty = true;
  const int play_wait = std::max(1, static_cast<int>(1000 / args.fps));
  for (;;) {
    if (dirty) {
      const Stopwatch clock;
      cv::imshow(kWindow, player.image());
      if (player.index() != shown) {
        if (shown != SIZE_MAX) step_ms.push_back(clock.ms());
        ++steps_shown;
        shown = player.index();
        // One line per step: the terminal keeps the path taken (and tests wait for it).
        spdlog::info("step {} / {}: {}", shown + 1, player.steps(),
                     viz::step_label(player.plan(), player.plan().steps[shown]));
      }
      dirty = false;
    }
    const int code = cv::waitKeyEx(player.playing() ? play_wait : 40);
    check_interrupt();
    if (cv::getWindowProperty(kWindow, cv::WND_PROP_VISIBLE) < 1) break;  // closed
    if (!clicks.points.empty()) {
      for (const cv::Point& p : clicks.points) player.click(p);
      clicks.points.clear();
      dirty = true;
    }
    if (code >= 0) {
      const std::string before = player.message();
      if (!player.key(code)) break;
      if (player.message() != before && player.message().rfind("saved ", 0) == 0)
        spdlog::info("{}", player.message());
      dirty = true;
    } else if (player.playing()) {
      player.tick();
      dirty = true;
    }
  }
  cv::destroyAllWindows();
  if (!step_ms.empty())
    spdlog::info("step: {} steps shown, median {:.1f} ms to render and show a step (max {:.1f})",
                 steps_shown, median(step_ms),
                 *std::max_element(step_ms.begin(), step_ms.end()));
}

}  // namespace

Command add_step_command(CLI::App& app) {
  auto args = std::make_shared<StepArgs>();
  // The keys as the window's `?` shows them: the players' key table (web/player/keys.json).
  std::string about =
      "Steps through the replay of a trace in a window, at your own pace: the frames\n"
      "of 'replay', rendered as you go. Takes a trace file (.jsonl) or the inputs of\n"
      "'trace'. Keys (every player's, web/player/keys.json; ? shows them):\n";
  for (const std::string& line : key_help_lines()) about += "  " + line + "\n";
  about +=
      "A selected pixel stays marked, and the side panel shows its history so far\n"
      "(which triangle, row and span wrote it, with which colour). Needs a display;\n"
      "without one, 'explain -o OUT.html' writes a page to step through in a browser.";
  CLI::App* cmd = app.add_subcommand("step", about);
  add_trace_flags(*cmd, args->what);
  cmd->get_option("SCENE")->description(
      "trace file (.jsonl, from 'scantrace trace'), or a scene file\n"
      "(JSON) or OBJ model to trace as 'trace' does");
  add_fill_flags(*cmd, args->fill);
  add_model_flags(*cmd, args->model, true);
  cmd->add_flag("--partial", args->partial,
                "step through a trace file that was cut short (no footer)");
  cmd->add_option("--video-size", args->size,
                  "window size WIDTHxHEIGHT, even: the frame and, below it,\n"
                  "the status line")
      ->check(parsed_by(parse_video_size))
      ->capture_default_str();
  cmd->add_option("--fps", args->fps, "steps per second when playing (a)")
      ->check(CLI::Range(0.1, 60.0))
      ->capture_default_str();
  cmd->add_option("--rows-per-step", args->rows_per_step,
                  "scanlines per step (0: automatic, at most 40 scanline\n"
                  "steps per triangle); r toggles one per scanline")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--mode", args->mode, "triangles, scene or auto (as for replay)")
      ->check(CLI::IsMember({"auto", "triangles", "scene"}))
      ->capture_default_str();
  cmd->add_option("--step", args->start, "the step to open at (from 1; past the last: the last)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--save-dir", args->save_dir, "where s writes step_NNNNN.png")
      ->capture_default_str();
  cmd->callback([args] {
    if (!is_trace_file(args->what.scene)) args->what.check(args->fill.fill_rule, args->fill.method);
  });
  cmd->footer(
      "Examples:\n"
      "  scantrace step triangle.jsonl\n"
      "  scantrace step --triangle \"20,20 250,80 300,400\"\n"
      "  scantrace step scene.json --video-size 1920x1080\n"
      "Without a display (exit status 1), write a page instead:\n"
      "  scantrace explain --triangle \"20,20 250,80 300,400\" -o triangle.html");
  return {cmd, [args] { run(*args); }};
}

}  // namespace scantrace::cli
