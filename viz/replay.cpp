#include "viz/replay.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>

#include "io/atomic_write.hpp"
#include "io/interrupt.hpp"
#include "viz/frame_directory.hpp"
#include "viz/html_player.hpp"
#include "viz/replayer.hpp"
#include "viz/svg_frame.hpp"
#include "viz/video_writer.hpp"

namespace scantrace::viz {
namespace {

std::size_t parse_step(const std::string& text, const std::string& whole) {
  std::size_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || v == 0)
    throw std::invalid_argument(
        fmt::format("--steps: \"{}\" is not A:B with steps counted from 1", whole));
  return v;
}

}  // namespace

StepRange StepRange::parse(const std::string& text) {
  StepRange r;
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) {
    r.first = r.last = parse_step(text, text);
    return r;
  }
  const std::string a = text.substr(0, colon), b = text.substr(colon + 1);
  if (a.empty() && b.empty())
    throw std::invalid_argument(fmt::format("--steps: \"{}\" names no step", text));
  if (!a.empty()) r.first = parse_step(a, text);
  if (!b.empty()) r.last = parse_step(b, text);
  if (r.first > r.last)
    throw std::invalid_argument(fmt::format("--steps: \"{}\" ends before it starts", text));
  return r;
}

void validate(const ReplayOptions& o) {
  if (o.size.width < kMinFrameWidth || o.size.height < kMinFrameHeight || o.size.width > 7680 ||
      o.size.height > 4320)
    throw std::invalid_argument(fmt::format("frame size {}x{} is out of range ({}x{} to 7680x4320)",
                                            o.size.width, o.size.height, kMinFrameWidth,
                                            kMinFrameHeight));
  if (o.size.width % 2 || o.size.height % 2)
    throw std::invalid_argument(
        fmt::format("frame size {}x{} must be even in both directions (4:2:0 video)", o.size.width,
                    o.size.height));
  if (!(o.fps > 0 && o.fps <= 240)) throw std::invalid_argument("fps must be in (0, 240]");
  if (!(o.hold > 0 && o.hold <= 60)) throw std::invalid_argument("hold must be in (0, 60] seconds");
  if (!(o.max_seconds > 0)) throw std::invalid_argument("the time budget must be positive");
  if (o.frame_format != "png" && o.frame_format != "svg")
    throw std::invalid_argument(
        fmt::format("--format: \"{}\" is neither png nor svg", o.frame_format));
  if (o.plan.rows_per_step < 0) throw std::invalid_argument("rows per step must be >= 0");
}

OutputKind output_kind(const std::filesystem::path& out) {
  const std::string s = out.string();
  if (s.empty()) throw std::invalid_argument("no output given");
  if (s.back() == '/') return OutputKind::frames;
  std::error_code ec;
  if (std::filesystem::is_directory(out, ec)) return OutputKind::frames;
  const std::string ext = out.extension().string();
  if (ext == ".mp4" || ext == ".MP4") return OutputKind::video;
  if (ext == ".html" || ext == ".htm" || ext == ".HTML") return OutputKind::html;
  if (ext == ".svg" || ext == ".SVG") return OutputKind::svg;
  if (ext.empty()) return OutputKind::frames;
  throw std::invalid_argument(
      fmt::format("{}: the output must be an .mp4 file, an .html page, an .svg file or a "
                  "directory (DIR/)",
                  s));
}

namespace {

// The steps a replay writes, [first, last] counted from 0.
struct Chosen {
  std::size_t first, last;
};

Chosen chosen_steps(const Replayer& replayer, const StepRange& steps) {
  const std::size_t total = replayer.steps().size();
  if (steps.first > total)
    throw std::invalid_argument(
        fmt::format("--steps: the replay has {} steps, so it has no step {}", total, steps.first));
  return {steps.first - 1, std::min(steps.last, total) - 1};
}

// The frames the replay will write (a video's steps held for their time, otherwise one a step):
// the progress counts them, and more than the budget is refused before anything is drawn.
std::size_t frames_to_write(const Replayer& replayer, Chosen c, const ReplayResult& result,
                            const ReplayOptions& options, const std::filesystem::path& out) {
  std::size_t work = result.steps;
  if (result.kind == OutputKind::video) {
    work = 0;
    for (std::size_t i = c.first; i <= c.last; ++i)
      work += static_cast<std::size_t>(frames_for(replayer.steps()[i], options.fps, options.hold));
  }
  if (work > options.max_frames)
    throw std::invalid_argument(fmt::format(
        "{}: the replay needs {} frames ({} steps), more than the budget of {} (--max-frames); "
        "choose fewer steps (--steps A:B, --rows-per-step N, fewer triangles) or raise the budget",
        out.string(), work, result.steps, options.max_frames));
  return work;
}

// SVG frames go to a directory or, one step, to an .svg file: not into a video or a page.
void check_svg_output(const ReplayOptions& options, const ReplayResult& result,
                      const std::filesystem::path& out) {
  if (options.frame_format == "svg" &&
      (result.kind == OutputKind::video || result.kind == OutputKind::html))
    throw std::invalid_argument(fmt::format(
        "{}: --format svg writes SVG frames to a directory (-o DIR/) or one step to OUT.svg",
        out.string()));
  if (result.kind == OutputKind::svg && result.steps != 1)
    throw std::invalid_argument(fmt::format(
        "{}: an .svg file holds one step and the replay has {} (choose one with --steps N, or "
        "write a directory: -o DIR/ --format svg)",
        out.string(), result.steps));
}

void write_page(Replayer& replayer, Chosen c, const std::filesystem::path& out,
                const ReplayOptions& options, Progress* progress, ReplayResult& result) {
  HtmlPlayerOptions page;
  page.source = options.source.empty() ? "the trace" : options.source;
  page.fps = options.fps;
  const HtmlPlayerResult h = write_html_player(replayer, c.first, c.last, out, page, progress);
  result.format = h.format;
  result.frames = h.steps;
  result.bytes = h.bytes;
}

void write_svg_directory(Replayer& replayer, Chosen c, const std::filesystem::path& out,
                         const ReplayOptions& options, std::size_t work, Progress* progress,
                         ReplayResult& result) {
  FrameDirectory dir(out, options.size, c.first + 1, "svg");
  const TimeBudget budget(out, options.max_seconds);
  for (std::size_t i = c.first; i <= c.last; ++i) {
    check_interrupt();
    dir.write_document(to_svg(replayer.display_list(i)));
    if (progress) progress->update(dir.frames(), work);
    budget.check(i - c.first + 1, result.steps);
  }
  dir.commit();
  if (progress) progress->finish();
  result.format = dir.format();
  result.frames = dir.frames();
}

// A video, or PNG frames in a directory: the raster frames through a FrameSink.
void write_raster(Replayer& replayer, Chosen c, const std::filesystem::path& out,
                  const ReplayOptions& options, std::size_t work, Progress* progress,
                  ReplayResult& result) {
  std::unique_ptr<FrameSink> sink;
  if (result.kind == OutputKind::video)
    sink = std::make_unique<VideoFile>(out, options.size, options.fps);
  else
    sink = std::make_unique<FrameDirectory>(out, options.size, c.first + 1);
  const TimeBudget budget(out, options.max_seconds);
  for (std::size_t i = c.first; i <= c.last; ++i) {
    check_interrupt();  // a long video: Ctrl-C stops here and the sink removes its temporary
    const int repeat = frames_for(replayer.steps()[i], options.fps, options.hold);
    sink->write(replayer.frame(i), repeat);
    if (progress) progress->update(sink->frames(), work);
    budget.check(i - c.first + 1, result.steps);  // steps drawn: a video's repeats cost little
  }
  sink->commit();
  if (progress) progress->finish();
  result.format = sink->format();
  result.frames = sink->frames();
  result.seconds = result.kind == OutputKind::video ? result.frames / options.fps : 0;
}

}  // namespace

ReplayResult replay(const trace::Trace& trace, const std::filesystem::path& out,
                    const ReplayOptions& options, Progress* progress) {
  validate(options);
  Replayer replayer(trace, options.plan, options.size,
                    options.source.empty() ? "the trace" : options.source);
  replayer.mark_on_every_frame(options.marked_pixel);
  const Chosen chosen = chosen_steps(replayer, options.steps);

  ReplayResult result;
  result.kind = output_kind(out);
  result.steps_total = replayer.steps().size();
  result.steps = chosen.last - chosen.first + 1;
  result.mode = replayer.plan().mode;
  result.rows_per_step = replayer.plan().rows_per_step;
  const std::size_t work = frames_to_write(replayer, chosen, result, options, out);
  if (result.kind == OutputKind::html) {
    write_page(replayer, chosen, out, options, progress, result);
    return result;
  }
  check_svg_output(options, result, out);
  if (result.kind == OutputKind::svg) {
    write_file_atomically(out, to_svg(replayer.display_list(chosen.first)));
    result.format = "svg";
    result.frames = 1;
  } else if (result.kind == OutputKind::frames && options.frame_format == "svg") {
    write_svg_directory(replayer, chosen, out, options, work, progress, result);
  } else {
    write_raster(replayer, chosen, out, options, work, progress, result);
  }
  return result;
}

}  // namespace scantrace::viz
