// The demo's explanation in scantrace-tools: the video and the page (cli/demo_explain.hpp).
#include <memory>

#include <spdlog/spdlog.h>

#include "cli/demo_explain.hpp"
#include "cli/stopwatch.hpp"
#include "cli/trace_page.hpp"
#include "trace/trace.hpp"
#include "viz/progress.hpp"
#include "viz/replay.hpp"

namespace scantrace::cli {

// The video and the page are made from the trace file just written, so they explain exactly what
// the file holds; it is read once for both.
void explain_demo_with_video(const std::filesystem::path& trace_file,
                             const std::filesystem::path& video,
                             const std::filesystem::path& page) {
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
  // The trace and its player when the web build is there (cli/trace_page.hpp); a build without
  // it (emscripten adds minutes of compiling) writes the page of pre-drawn frames, and the line
  // says how to get the small one.
  if (!trace_page_template().empty()) {
    const std::size_t bytes = write_trace_page(t, options, page);
    spdlog::info(
        "wrote {}: the same steps as a self-contained page (the trace and its player, {:.0f} KB): "
        "open it in a browser and step with the arrow keys",
        page.string(), bytes / 1e3);
    return;
  }
  const viz::ReplayResult p = replay_to(page);
  spdlog::info(
      "wrote {}: the same steps as a self-contained page ({} steps, {:.1f} MB of pre-drawn "
      "frames: this build has no web build; `bash scripts/build.sh --web`, then `scantrace replay "
      "{} -o {}`, writes the trace page of under 400 KB): open it in a browser and step with the "
      "arrow keys",
      page.string(), p.steps, p.bytes / 1e6, trace_file.string(), page.string());
}

}  // namespace scantrace::cli
