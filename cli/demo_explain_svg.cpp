// The demo's explanation in `scantrace` when scantrace-tools is not built (the demo's build,
// without OpenCV): the page of SVG frames, and how to make the video (cli/demo_explain.hpp).
#include <memory>

#include <spdlog/spdlog.h>

#include "cli/demo_explain.hpp"
#include "cli/stopwatch.hpp"
#include "trace/trace.hpp"
#include "viz/progress.hpp"
#include "viz/step_page.hpp"

namespace scantrace::cli {

void explain_demo_with_svg(const std::filesystem::path& trace_file,
                           const std::filesystem::path& video, const std::filesystem::path& page) {
  const trace::Trace t = trace::Trace::load(trace_file);
  // The frame size and step plan of `scantrace replay`'s defaults (viz/replay.hpp), so that the
  // page shows the frames the video and the full build's page show.
  viz::FrameSequence frames(t, viz::StepOptions{}, {1280, 720}, trace_file.string());
  std::unique_ptr<viz::Progress> progress;
  if (spdlog::should_log(spdlog::level::info))
    progress = std::make_unique<viz::StderrProgress>(page.string(), "frames");
  viz::HtmlPlayerOptions options;
  options.source = trace_file.string();
  const Stopwatch clock;
  const viz::HtmlPlayerResult r =
      viz::write_svg_step_page(frames, 0, frames.steps().size() - 1, page, options, progress.get());
  spdlog::info(
      "wrote {}: the steps of that trace as a self-contained page ({} steps, SVG frames, {:.1f} "
      "MB, made in {:.1f} s): open it in a browser and step with the arrow keys",
      page.string(), r.steps, r.bytes / 1e6, clock.ms() / 1000);
  spdlog::info(
      "the video of these steps ({}) needs OpenCV, which the demo's build leaves out: after "
      "'bash scripts/test.sh', run: scantrace replay {} -o {}",
      video.filename().string(), trace_file.string(), video.string());
}

}  // namespace scantrace::cli
