#include "cli/replay_flags.hpp"

#include <charconv>
#include <memory>
#include <stdexcept>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "cli/deprecated_option.hpp"
#include "cli/validators.hpp"

#include "cli/stopwatch.hpp"
#include "cli/trace_page.hpp"
#include "viz/progress.hpp"

namespace scantrace::cli {

cv::Size parse_video_size(const std::string& text) {
  const std::size_t x = text.find('x');
  int w = 0, h = 0;
  const char* s = text.data();
  const char* end = s + text.size();
  bool ok = x != std::string::npos;
  if (ok) {
    const auto a = std::from_chars(s, s + x, w);
    const auto b = std::from_chars(s + x + 1, end, h);
    ok = a.ec == std::errc() && a.ptr == s + x && b.ec == std::errc() && b.ptr == end;
  }
  if (!ok) throw std::invalid_argument("\"" + text + "\" is not WIDTHxHEIGHT, e.g. 1280x720");
  viz::ReplayOptions probe;
  probe.size = {w, h};
  viz::validate(probe);  // the one place that knows the limits (even, 320x180 .. 7680x4320)
  return probe.size;
}

viz::ReplayOptions ReplayFlags::options(const std::string& source) const {
  viz::ReplayOptions o;
  o.size = parse_video_size(size);
  o.fps = fps;
  o.hold = hold;
  if (!steps.empty()) o.steps = viz::StepRange::parse(steps);
  o.plan.rows_per_step = rows_per_step;
  o.plan.mode = viz::parse_replay_mode(mode);
  o.source = source;
  o.max_frames = max_frames;
  o.max_seconds = max_minutes * 60;
  o.marked_pixel = marked_pixel;
  o.frame_format = format;
  return o;
}

void add_replay_flags(CLI::App& command, ReplayFlags& flags, bool size_is_free) {
  command
      .add_option("-o,--output", flags.output,
                  "OUT.mp4: an H.264 video (MPEG-4 where H.264 is missing)\n"
                  "OUT_DIR/: numbered PNG frames, one per step\n"
                  "OUT.html: one self-contained page to step through\n"
                  "(slider, keys, play; OUT.html#step=N links to step N)\n"
                  "OUT.svg: the SVG of the one step --steps N names")
      ->required()
      ->check(parsed_by([](const std::string& v) { viz::output_kind(v); }));
  command
      .add_option("--fps", flags.fps,
                  "video frames per second (an HTML page plays\nsteps at this rate)")
      ->check(CLI::Range(0.1, 240.0))
      ->capture_default_str();
  command
      .add_option("--hold", flags.hold,
                  "seconds a scanline step stays on screen; cards,\n"
                  "set-up and edge-table steps stay 2-3x as long")
      ->check(CLI::Range(0.01, 60.0))
      ->capture_default_str();
  command
      .add_option("--video-size", flags.size,
                  "frame size WIDTHxHEIGHT of the video or PNG frames,\n"
                  "even (e.g. 1920x1080)")
      ->check(parsed_by(parse_video_size))
      ->capture_default_str();
  // --size is the canvas on every command that takes a scene; replay once used it for the frame.
  if (size_is_free)
    add_deprecated_alias(command, "--size", "--video-size", flags.size)
        ->check(parsed_by(parse_video_size));
  command
      .add_option("--steps", flags.steps, "render only steps A..B (from 1; \"5:\", \":20\", \"7\")")
      ->check(parsed_by([](const std::string& v) { viz::StepRange::parse(v); }));
  command
      .add_option("--rows-per-step", flags.rows_per_step,
                  "scanlines per step (0: automatic, at most 40 scanline\n"
                  "steps per triangle)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command
      .add_option("--mode", flags.mode,
                  "triangles: each triangle step by step\n"
                  "scene: the triangles in batches, under the trace's\n"
                  "visibility rule (painter's order or z-buffer)\n"
                  "auto: triangles for one triangle, scene for more")
      ->check(CLI::IsMember({"auto", "triangles", "scene"}))
      ->capture_default_str();
  command
      .add_option("--format", flags.format,
                  "the files of OUT_DIR/: png (raster frames) or svg\n"
                  "(vector frames, self-contained SVG 1.1)")
      ->check(CLI::IsMember({"png", "svg"}))
      ->capture_default_str();
  command.add_flag("--frames-page", flags.frames_page,
                   "OUT.html: embed every frame pre-drawn (WebP, megabytes)\n"
                   "instead of the trace and its player, which compose\n"
                   "the frames in the browser (kilobytes; written when\n"
                   "the web build is there, docs/web.md)");
  command
      .add_option("--max-frames", flags.max_frames,
                  "refuse (before drawing) a replay that needs more frames")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command
      .add_option("--max-minutes", flags.max_minutes,
                  "stop (writing nothing) a replay that, at the rate of its\n"
                  "first frames, would take longer to draw")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

void run_replay(const trace::Trace& trace, const ReplayFlags& flags, const std::string& source) {
  const viz::ReplayOptions options = flags.options(source);
  std::unique_ptr<viz::Progress> progress;
  if (spdlog::should_log(spdlog::level::info))
    progress = std::make_unique<viz::StderrProgress>(flags.output, "frames");
  const Stopwatch clock;
  if (viz::output_kind(flags.output) == viz::OutputKind::html && !flags.frames_page &&
      !trace_page_template().empty()) {
    viz::validate(options);
    const std::size_t bytes = write_trace_page(trace, options, flags.output);
    spdlog::info(
        "wrote {}: the trace and its player, a self-contained page of {:.0f} KB, in {:.1f} s; "
        "open it in a browser (#step=N links to step N)",
        flags.output, bytes / 1e3, clock.ms() / 1000);
    return;
  }
  const viz::ReplayResult r = viz::replay(trace, flags.output, options, progress.get());
  const std::string steps = r.steps == r.steps_total ? std::to_string(r.steps) + " steps"
                                                     : std::to_string(r.steps) + " of " +
                                                           std::to_string(r.steps_total) + " steps";
  if (r.kind == viz::OutputKind::html)
    spdlog::info(
        "wrote {}: {} ({}), a self-contained page of {}x{} lossless {} frames, {:.1f} MB, in "
        "{:.1f} s; open it in a browser (#step=N links to step N)",
        flags.output, steps, viz::to_string(r.mode), options.size.width, options.size.height,
        r.format == "webp" ? "WebP" : r.format, r.bytes / 1e6, clock.ms() / 1000);
  else if (r.kind == viz::OutputKind::video)
    spdlog::info("wrote {}: {} ({}), {} {}x{}, {} frames at {} fps = {:.1f} s, in {:.1f} s",
                 flags.output, steps, viz::to_string(r.mode),
                 r.format == "h264" ? "H.264" : "MPEG-4", options.size.width, options.size.height,
                 r.frames, options.fps, r.seconds, clock.ms() / 1000);
  else if (r.kind == viz::OutputKind::svg)
    spdlog::info("wrote {}: step {} of {} ({}), a {}x{} SVG, in {:.1f} s", flags.output,
                 options.steps.first, r.steps_total, viz::to_string(r.mode), options.size.width,
                 options.size.height, clock.ms() / 1000);
  else
    spdlog::info("wrote {}: {} ({}), one {}x{} {} per step, in {:.1f} s", flags.output, steps,
                 viz::to_string(r.mode), options.size.width, options.size.height,
                 r.format == "svg" ? "SVG" : "PNG", clock.ms() / 1000);
}

}  // namespace scantrace::cli
