// Render time of whole scenes: the built-in demo scene and, when ../shared/data is present, the
// course scene (10,000 triangles), flat and Gouraud. Reported as medians over repetitions (the
// machines are shared and noisy); pass --benchmark_* flags to override the defaults.
//
//   build/bench/bench_render [--scene FILE]
#include <benchmark/benchmark.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "demo/demo_scene.hpp"
#include "io/scene_json.hpp"
#include "src/painter.hpp"

namespace {

using namespace scantrace;

void register_scene(const std::string& name, const Scene& scene) {
  for (Shading shading : {Shading::flat, Shading::gouraud}) {
    const std::string label = name + "/" + to_string(shading);
    benchmark::RegisterBenchmark(label.c_str(), [scene, shading](benchmark::State& state) {
      RenderStats stats;
      for (auto _ : state) {
        RgbImage image = render(scene, FillOptions{.shading = shading}, &stats);
        benchmark::DoNotOptimize(image.pixels().data());
      }
      state.counters["triangles/s"] = benchmark::Counter(
          static_cast<double>(scene.faces.size()), benchmark::Counter::kIsIterationInvariantRate);
      state.counters["pixels/s"] = benchmark::Counter(
          static_cast<double>(stats.pixels), benchmark::Counter::kIsIterationInvariantRate);
    })->Unit(benchmark::kMicrosecond);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<char*> args(argv, argv + argc);
  std::string scene_file = SCANTRACE_SHARED_DATA "/hw1_2024.json";
  for (std::size_t i = 1; i + 1 < args.size(); ++i)
    if (std::strcmp(args[i], "--scene") == 0) {
      scene_file = args[i + 1];
      args.erase(args.begin() + i, args.begin() + i + 2);
      break;
    }
  bool has_repetitions = false;
  for (char* a : args) has_repetitions |= std::strncmp(a, "--benchmark_repetitions", 23) == 0;
  static char reps[] = "--benchmark_repetitions=15";
  static char aggregates[] = "--benchmark_report_aggregates_only=true";
  if (!has_repetitions) {
    args.push_back(reps);
    args.push_back(aggregates);
  }
  int n = static_cast<int>(args.size());
  benchmark::Initialize(&n, args.data());

  register_scene("demo_scene", demo_scene());
  if (std::filesystem::exists(scene_file))
    register_scene("course_scene", load_scene(scene_file));
  else
    std::fprintf(stderr, "note: %s not found; benchmarking the demo scene only\n",
                 scene_file.c_str());

  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
