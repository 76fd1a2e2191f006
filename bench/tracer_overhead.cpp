// What tracing costs. Prints the median time of rendering a scene (the course scene when
// ../shared/data is present, else the built-in demo scene) in each mode:
//   untraced      render() with the default no-op tracer
//   one-triangle  render() under an event tracer that records one triangle (scanline level)
// The same source is also built with SCANTRACE_NO_TRACE_HOOKS (bench_tracer_overhead_nohooks),
// where the fill has no hook at all; scripts/bench_tracer_overhead.sh runs both side by side.
//
//   bench_tracer_overhead [--scene FILE] [--repetitions N] [--mode untraced|one-triangle|all]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "demo/demo_scene.hpp"
#include "io/scene_json.hpp"
#include "src/painter.hpp"
#include "trace/event_tracer.hpp"
#include "trace/recorder.hpp"

namespace scantrace::bench {
float render_untraced(const Scene& scene, const FillOptions& options);  // untraced_render.cpp
}

namespace {

using namespace scantrace;
using Clock = std::chrono::steady_clock;

template <class Fn>
double median_us(int repetitions, Fn&& fn) {
  fn();  // warm-up: page faults, caches
  std::vector<double> us;
  for (int i = 0; i < repetitions; ++i) {
    const auto t0 = Clock::now();
    fn();
    us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
  }
  std::nth_element(us.begin(), us.begin() + us.size() / 2, us.end());
  return us[us.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_file = SCANTRACE_SHARED_DATA "/hw1_2024.json", mode = "all";
  int repetitions = 41;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--scene"))
      scene_file = argv[i + 1];
    else if (!std::strcmp(argv[i], "--repetitions"))
      repetitions = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--mode"))
      mode = argv[i + 1];
  }
  const bool course = std::filesystem::exists(scene_file);
  const Scene scene = course ? load_scene(scene_file) : demo_scene();
  const FillOptions options{.shading = Shading::gouraud};
  volatile float sink = 0;

  if (mode == "untraced" || mode == "all") {
    const double t = median_us(repetitions, [&] { sink = bench::render_untraced(scene, options); });
    std::printf("untraced %.1f\n", t);
  }
  if (mode == "one-triangle" || mode == "all") {
    const int face = static_cast<int>(scene.faces.size() / 2);
    const double t = median_us(repetitions, [&] {
      trace::TraceFilter filter;
      filter.triangles = trace::IndexSet::parse(std::to_string(face));
      trace::EventTracer<trace::Recorder> tracer(
          trace::Recorder(trace::make_header(scene.width, scene.height, options, filter.level)),
          filter);
      sink = render(scene, options, tracer)(7, 7).r;
      sink = static_cast<float>(tracer.finish().events().size());
    });
    std::printf("one-triangle %.1f\n", t);
  }
  std::fprintf(stderr, "scene: %s (%zu faces), %d repetitions\n",
               course ? scene_file.c_str() : "built-in demo scene", scene.faces.size(),
               repetitions);
  return 0;
}
