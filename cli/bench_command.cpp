// scantrace bench [--scene FILE] [--rounds N] [--quick] [-o PREFIX]
// The runtime-vs-error benchmark: every method of the fill and OpenCV's cv::fillConvexPoly on the
// same workloads in the same process, timed side by side (interleaved rounds, medians), with
// their errors against the exact reference, the physical limit of the pixel stores, what the fill
// skips, and the parallel render. Markdown on stdout, PREFIX.csv and PREFIX.png.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <opencv2/core.hpp>

#include "bench/accuracy.hpp"
#include "bench/allocation_counter.hpp"
#include "bench/bench_cases.hpp"
#include "bench/bench_table.hpp"
#include "bench/child_process.hpp"
#include "bench/opencv_scene.hpp"
#include "bench/timing.hpp"
#include "cli/commands.hpp"
#include "demo/demo_scene.hpp"
#include "io/atomic_write.hpp"
#include "io/scene_json.hpp"
#include "src/band_render.hpp"
#include "src/painter.hpp"
#include "stress/opencv_rasterizer.hpp"
#include "trace/event_tracer.hpp"
#include "trace/recorder.hpp"

namespace scantrace::cli {
namespace {

using bench::Job;
using bench::Measurement;

struct BenchArgs {
  // No default: a path outside the repository would make the report depend on where the command
  // runs. Without --scene the course scene's rows are left out and the report says so.
  std::string scene;
  int rounds = 15;
  bool quick = false;
  std::string prefix = "scantrace-bench";
};

volatile unsigned g_sink = 0;  // keeps renders from being optimised away

Measurement measurement(const std::string& workload, const std::string& variant,
                        const std::string& shading, const std::string& image) {
  Measurement m;
  m.workload = workload, m.variant = variant, m.shading = shading, m.image = image;
  return m;
}

constexpr Method kMethods[] = {Method::exact, Method::float32, Method::double64, Method::halfspace};

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// Pixels the painter's exact flat fill writes for the scene, far to near (what the memset limit
// must write too: the workload as the course's algorithm defines it).
long long pixels_written(const Scene& s) {
  RenderStats stats;
  render<Bgr8>(s, FillOptions{.shading = Shading::flat, .occlusion = Occlusion::far_to_near},
               &stats);
  return stats.pixels;
}

// A render into an image and a scratch the job keeps from run to run, as a caller who renders
// repeatedly does (OpenCV's job likewise reuses its cv::Mat): what is timed is the clear and the
// fill, not the allocation and first-touch page faults of a fresh image.
template <class P>
Job warm_render(std::string name, const Scene& scene, FillOptions opt, int threads = 1) {
  auto image = std::make_shared<Image<P>>();
  auto scratch = std::make_shared<RenderScratch>();
  return {std::move(name), [&scene, opt, threads, image, scratch] {
            if (threads == 1)
              render(*image, scene, opt, *scratch);
            else
              render_parallel(*image, scene, opt, threads, *scratch);
            g_sink = g_sink + (image->row(0)[0] == image->row(0)[1]);
          }};
}

struct Workload {
  std::string name;
  Scene scene;
  bool accuracy = true;
};

class Bench {
 public:
  explicit Bench(const BenchArgs& a) : args_(a) {}

  // Every method × shading, OpenCV flat and the memset limit on one workload.
  void compare(const Workload& w) {
    spdlog::info("bench: {} ({} triangles)", w.name, w.scene.faces.size());
    const long long pixels = pixels_written(w.scene);
    std::vector<Job> jobs;
    std::vector<Measurement> rows;
    // Each method far to near, every face painted, as OpenCV's render paints them: the fills
    // compared on the same work.
    for (Method m : kMethods)
      for (Shading sh : {Shading::flat, Shading::gouraud}) {
        const FillOptions opt{.shading = sh, .method = m, .occlusion = Occlusion::far_to_near};
        jobs.push_back(warm_render<Bgr8>(to_string(m), w.scene, opt));
        rows.push_back(measurement(w.name, to_string(m), to_string(sh), "8-bit"));
      }
    const std::size_t methods = rows.size();
    // The default render, which may draw near to far (occlusion_choice.hpp): what render() gives.
    for (Shading sh : {Shading::flat, Shading::gouraud}) {
      jobs.push_back(warm_render<Bgr8>("default (exact)", w.scene, FillOptions{.shading = sh}));
      rows.push_back(measurement(w.name, "default (exact)", to_string(sh), "8-bit"));
    }
    const bench::OpenCvScene ocv(w.scene);
    cv::Mat ocv_image;
    jobs.push_back({"opencv", [&] { ocv.render(ocv_image); }});
    rows.push_back(measurement(w.name, "opencv", "flat", "8-bit"));
    // The physical limit: the same number of 8-bit pixels stored at memcpy speed into a buffer
    // that is already allocated (no clear, no geometry).
    Bgr8Image limit(static_cast<int>(std::max<long long>(pixels, 1)), 1);
    jobs.push_back({"memset", [&] { limit.fill_all(Bgr8{7, 8, 9}); }});
    rows.push_back(measurement(w.name, "memset", "", "8-bit"));

    const std::vector<double> t = bench::time_interleaved(jobs, args_.rounds);
    const double opencv = t[t.size() - 2];
    for (std::size_t i = 0; i < rows.size(); ++i) {
      rows[i].seconds = t[i];
      rows[i].triangles = rows[i].variant == "memset" ? 0 : w.scene.faces.size();
      rows[i].pixels = pixels;
      if (rows[i].variant != "memset") rows[i].vs_opencv = t[i] / opencv;
    }
    if (w.accuracy) {
      for (std::size_t i = 0; i < methods; i += 2) {
        auto r = stress::make_method(kMethods[i / 2]);
        const bench::Accuracy a = bench::measure_accuracy(*r, w.scene);
        rows[i].wrong_per_million = rows[i + 1].wrong_per_million = a.wrong_per_million();
        rows[i + 1].colour_max = a.colour_max;
      }
      auto r = stress::make_opencv_rasterizer();
      rows[rows.size() - 2].wrong_per_million =
          bench::measure_accuracy(*r, w.scene).wrong_per_million();
    }
    print_table(w.name, rows);
    all_.insert(all_.end(), rows.begin(), rows.end());
  }

  const std::vector<Measurement>& rows() const { return all_; }
  void add(const Measurement& m) { all_.push_back(m); }

  static void sink(const Bgr8Image& image) { g_sink = g_sink + image.row(0)[0].g; }

  void print_table(const std::string& name, const std::vector<Measurement>& rows) const {
    std::printf("\n### %s\n\n", name.c_str());
    std::printf(
        "| fill | shading | median ms | triangles/s | pixels/s | × OpenCV flat | "
        "wrong px per 10⁶ | max colour error |\n|---|---|---:|---:|---:|---:|---:|---:|\n");
    for (const Measurement& m : rows)
      std::printf("| %s | %s | %.3f | %s | %s | %s | %s | %s |\n", m.variant.c_str(),
                  m.shading.empty() ? "—" : m.shading.c_str(), m.seconds * 1e3,
                  m.triangles ? fmt("%.3g", m.triangles / m.seconds).c_str() : "—",
                  fmt("%.3g", m.pixels / m.seconds).c_str(),
                  m.vs_opencv ? fmt("%.3f", *m.vs_opencv).c_str() : "—",
                  m.wrong_per_million ? fmt("%.3g", *m.wrong_per_million).c_str() : "—",
                  m.colour_max ? fmt("%.2g", *m.colour_max).c_str() : "—");
  }

 private:
  BenchArgs args_;
  std::vector<Measurement> all_;
};

const Measurement* find(const std::vector<Measurement>& rows, const std::string& workload,
                        const std::string& variant, const std::string& shading) {
  for (const Measurement& m : rows)
    if (m.workload == workload && m.variant == variant && m.shading == shading) return &m;
  return nullptr;
}

struct Target {
  std::string what;
  double measured;
  std::string goal;
  bool met;
};

void print_targets(const std::vector<Target>& targets) {
  std::printf("\n## Targets (ratios of medians measured side by side in this run)\n\n");
  std::printf("| target | measured | goal | met |\n|---|---:|---:|---|\n");
  for (const Target& t : targets)
    std::printf("| %s | %.3f | %s | %s |\n", t.what.c_str(), t.measured, t.goal.c_str(),
                t.met ? "yes" : "**no**");
}

// What the sections of the bench share: the options, the workloads every method is compared on
// (the first is the main scene: the course's, or the built-in one), the rows measured and the
// targets found.
struct BenchRun {
  const BenchArgs& args;
  bool course = false;
  std::vector<Workload> workloads;
  Bench bench;
  std::vector<Target> targets;
};

// The canvas of the half-canvas triangle: 4096², 1024² with --quick (whose table and target
// headings must say which).
int half_canvas_size(const BenchArgs& args) {
  return args.quick ? 1024 : 4096;
}

std::string half_canvas_name(const BenchArgs& args) {
  return "half of " + std::to_string(half_canvas_size(args)) + "² (one triangle)";
}

// The workloads every method, OpenCV and the memset limit are compared on, in the report's order:
// name, how it is made, and whether its accuracy is measured.
struct WorkloadSpec {
  const char* name;  // nullptr: named by the function (the half canvas)
  Scene (*make)(const BenchArgs&);
  bool (*accuracy)(const BenchArgs&);
};

bool always(const BenchArgs&) {
  return true;
}
bool unless_quick(const BenchArgs& a) {
  return !a.quick;
}
int small_count(const BenchArgs& a) {
  return a.quick ? 2000 : 10000;
}

constexpr WorkloadSpec kWorkloads[] = {
    {"course scene", [](const BenchArgs& a) { return load_scene(a.scene); }, always},
    {"built-in scene", [](const BenchArgs&) { return demo_scene(); }, always},
    {"small triangles (10 px²)",
     [](const BenchArgs& a) { return bench::small_triangles(1, 512, 512, small_count(a), 10); },
     always},
    {"small triangles (70 px²)",
     [](const BenchArgs& a) { return bench::small_triangles(2, 512, 512, small_count(a), 70); },
     always},
    // Its accuracy (every face in 6 vertex orders against the exact reference) takes minutes.
    {nullptr, [](const BenchArgs& a) { return bench::half_canvas_triangle(half_canvas_size(a)); },
     unless_quick},
    {"vertex at −1e9", [](const BenchArgs&) { return bench::far_vertex_triangle(); }, always},
    {"vertex at −1e9: visible part alone",
     [](const BenchArgs&) { return bench::far_vertex_visible_part(); }, always},
};

std::vector<Workload> make_workloads(const BenchArgs& args, bool course) {
  std::vector<Workload> out;
  for (const WorkloadSpec& w : kWorkloads) {
    const std::string name = w.name ? w.name : half_canvas_name(args);
    if (name == "course scene" && !course) continue;
    out.push_back({name, w.make(args), w.accuracy(args)});
  }
  return out;
}

// Every method × shading, OpenCV flat and the memset limit on each workload; the targets on the
// main scene, the small triangles, the half canvas and the far vertex.
void compare_methods(BenchRun& run) {
  for (const Workload& w : run.workloads) run.bench.compare(w);
  const auto& rows = run.bench.rows();
  const auto ratio = [&](const std::string& w, const std::string& v, const std::string& sh,
                         const std::string& w2, const std::string& v2, const std::string& sh2) {
    const Measurement *a = find(rows, w, v, sh), *c = find(rows, w2, v2, sh2);
    return a && c ? a->seconds / c->seconds : NAN;
  };
  auto& targets = run.targets;
  const std::string main_scene = run.workloads.front().name;
  targets.push_back({main_scene + ", flat: time / OpenCV time",
                     ratio(main_scene, "exact", "flat", main_scene, "opencv", "flat"), "≤ 0.35",
                     false});
  targets.push_back(
      {main_scene + ", Gouraud: time / OpenCV flat time",
       ratio(main_scene, "exact", to_string(Shading::gouraud), main_scene, "opencv", "flat"),
       "≤ 0.5", false});
  // The same with the default render, which draws the course scene near to far (it chooses so).
  targets.push_back({main_scene + ", flat, the default render: time / OpenCV time",
                     ratio(main_scene, "default (exact)", "flat", main_scene, "opencv", "flat"),
                     "≤ 0.35", false});
  targets.push_back({main_scene + ", Gouraud, the default render: time / OpenCV flat time",
                     ratio(main_scene, "default (exact)", to_string(Shading::gouraud), main_scene,
                           "opencv", "flat"),
                     "≤ 0.5", false});
  for (const char* w : {"small triangles (10 px²)", "small triangles (70 px²)"})
    targets.push_back({std::string(w) + ": triangles/s / OpenCV's",
                       1 / ratio(w, "exact", "flat", w, "opencv", "flat"), "≥ 3", false});
  const std::string half = half_canvas_name(run.args);
  if (!run.args.quick)
    targets.push_back({half + ", render into the caller's image (flat): time / OpenCV's (same "
                              "image reused)",
                       ratio(half, "exact", "flat", half, "opencv", "flat"), "≤ 1", false});
  targets.push_back({"vertex at −1e9: time / its visible part's time (flat)",
                     ratio("vertex at −1e9", "exact", "flat", "vertex at −1e9: visible part alone",
                           "exact", "flat"),
                     "≤ 2", false});
}

// The pixel rate of a large triangle against the physical limit: the fill alone, into a canvas
// that is already allocated and cleared (a render also allocates and clears the whole 4096² image,
// 48 MB, which is not the fill's work), against memset-class stores of the same pixels.
void half_canvas_limit(BenchRun& run) {
  const int size = half_canvas_size(run.args);
  const Scene half = bench::half_canvas_triangle(size);
  const long long pixels = pixels_written(half);
  Bgr8Image image(size, size, Bgr8{255, 255, 255});
  ImageCanvas<Bgr8> canvas(image);
  FillScratch scratch;
  const FaceCorners corners = corners_of(half, half.faces[0]);
  const std::array<Vec2, 3>& v = corners.points;
  const std::array<Color, 3>& c = corners.colors;
  Bgr8Image limit(static_cast<int>(pixels), 1);
  std::vector<Job> jobs;
  for (Shading sh : {Shading::flat, Shading::gouraud})
    jobs.push_back({to_string(sh), [&, sh] {
                      fill_polygon(canvas, PolygonInput{v, c, 0, std::nullopt},
                                   FillOptions{.shading = sh}, scratch);
                    }});
  jobs.push_back({"memset", [&] { limit.fill_all(Bgr8{7, 8, 9}); }});
  // memset itself, of a one-byte value, for comparison: glibc writes it with `rep stosb`, which
  // no store of a 3-byte pattern matches (docs/performance.md, "The clear"). The targets are
  // against the pixel limit above, the fastest a store of the canvas can be.
  jobs.push_back({"memset of one byte", [&] {
                    std::memset(static_cast<void*>(limit.row(0)), 7,
                                static_cast<std::size_t>(pixels) * sizeof(Bgr8));
                  }});
  const std::vector<double> t = bench::time_interleaved(jobs, run.args.rounds);
  std::printf(
      "\n## One triangle over half of a %d² canvas: the fill against the memset limit\n\n"
      "| | median ms | pixels/s | rate / memset rate | rate / one-byte memset's |\n"
      "|---|---:|---:|---:|---:|\n",
      size);
  const char* names[] = {"exact, flat", "exact, Gouraud",
                         "memset-class stores (a pixel block copied over the pixels)",
                         "memset of a one-byte value"};
  for (int i = 0; i < 4; ++i)
    std::printf("| %s | %.3f | %.3g | %.3f | %.3f |\n", names[i], t[i] * 1e3, pixels / t[i],
                t[2] / t[i], t[3] / t[i]);
  run.targets.push_back(
      {"half canvas, flat: pixel rate / memset rate", t[2] / t[0], "≥ 0.9", false});
  run.targets.push_back(
      {"half canvas, Gouraud: pixel rate / memset rate", t[2] / t[1], "≥ 0.5", false});
}

// The float canvas of the course, against the 8-bit one.
void float_canvas(BenchRun& run) {
  const Workload& w = run.workloads.front();
  std::vector<Job> jobs;
  for (Shading sh : {Shading::flat, Shading::gouraud}) {
    const FillOptions opt{.shading = sh, .occlusion = Occlusion::far_to_near};
    jobs.push_back(warm_render<Bgr8>("8-bit", w.scene, opt));
    jobs.push_back(warm_render<Rgb32f>("float", w.scene, opt));
  }
  const std::vector<double> t = bench::time_interleaved(jobs, run.args.rounds);
  std::printf("\n## The float canvas (the course's [0,1] RGB floats), %s\n\n", w.name.c_str());
  std::printf("| shading | 8-bit ms | float ms | float / 8-bit |\n|---|---:|---:|---:|\n");
  for (int i = 0; i < 2; ++i) {
    std::printf("| %s | %.3f | %.3f | %.2f |\n", to_string(Shading(i)), t[2 * i] * 1e3,
                t[2 * i + 1] * 1e3, t[2 * i + 1] / t[2 * i]);
    Measurement m = measurement(w.name, "exact", to_string(Shading(i)), "float");
    m.seconds = t[2 * i + 1];
    m.triangles = static_cast<long long>(w.scene.faces.size());
    run.bench.add(m);
  }
}

// What the fill skips: off-canvas, zero-area and equal-colour faces.
void fill_skips(BenchRun& run) {
  const int n = 10000;
  const Scene off = bench::offscreen_triangles(n), zero = bench::zero_area_triangles(n);
  const Scene uniform = bench::uniform_colour_triangles(3, n);
  const Scene varied = bench::small_triangles(3, 512, 512, n, 70);
  const FillOptions gouraud{.shading = Shading::gouraud}, flat{.shading = Shading::flat};
  Scene empty_scene;
  empty_scene.width = empty_scene.height = 512;
  std::vector<Job> jobs{
      warm_render<Bgr8>("offscreen", off, gouraud),
      warm_render<Bgr8>("zero area", zero, gouraud),
      warm_render<Bgr8>("uniform gouraud", uniform, gouraud),
      warm_render<Bgr8>("uniform flat", uniform, flat),
      warm_render<Bgr8>("varied gouraud", varied, gouraud),
      warm_render<Bgr8>("empty", empty_scene, gouraud),
  };
  const std::vector<double> t = bench::time_interleaved(jobs, run.args.rounds);
  RenderStats s_off, s_zero;
  render<Bgr8>(off, gouraud, &s_off);
  render<Bgr8>(zero, gouraud, &s_zero);
  FillScratch scratch;
  long long rows_off = 0, rows_zero = 0;
  for (const auto& [scene, rows_visited] :
       {std::pair{&off, &rows_off}, std::pair{&zero, &rows_zero}}) {
    Bgr8Image image(512, 512);
    ImageCanvas<Bgr8> canvas(image);
    for (const auto& f : scene->faces) {
      const FaceCorners c = corners_of(*scene, f);
      *rows_visited +=
          fill_polygon(canvas, PolygonInput{c.points, c.colors, 0, std::nullopt}, gouraud, scratch)
              .rows;
    }
  }
  const double empty = t[5];
  std::printf(
      "\n## What the fill skips (%d triangles each; the empty scene's clear and sort "
      "subtracted)\n\n",
      n);
  std::printf("| workload | ns per triangle | rows visited | note |\n|---|---:|---:|---|\n");
  std::printf("| off the canvas | %.1f | %lld | rejected by the bounding box, %lld skipped |\n",
              1e9 * (t[0] - empty) / n, rows_off, s_off.triangles_skipped);
  std::printf("| zero area | %.1f | %lld | rejected by the exact area, %lld skipped |\n",
              1e9 * (t[1] - empty) / n, rows_zero, s_zero.triangles_skipped);
  std::printf(
      "| Gouraud, three equal colours | %.1f | | flat path: %.2f × the flat fill, %.2f × "
      "Gouraud with distinct colours |\n",
      1e9 * (t[2] - empty) / n, (t[2] - empty) / (t[3] - empty), (t[2] - empty) / (t[4] - empty));
}

// The next rows of the table above. Allocations: a render into the caller's image with a kept
// scratch allocates nothing once warm; a render that returns a fresh image allocates it and the
// scratch, never per triangle or per row.
void allocations(BenchRun& run) {
  const FillOptions gouraud{.shading = Shading::gouraud};
  const Scene& scene = run.workloads.front().scene;
  Bgr8Image image;
  RenderScratch scratch;
  render(image, scene, gouraud, scratch);
  const long long before = bench::allocations_so_far();
  render(image, scene, gouraud, scratch);
  const long long warm = bench::allocations_so_far() - before;
  Bench::sink(render<Bgr8>(scene, gouraud));
  const long long before_fresh = bench::allocations_so_far();
  Bench::sink(render<Bgr8>(scene, gouraud));
  const long long fresh = bench::allocations_so_far() - before_fresh;
  std::printf(
      "| allocations in one render of the %s (%zu triangles) | %lld | | into the caller's "
      "image with a kept RenderScratch; %lld when it returns a fresh image (depths, sort "
      "buffers, fill scratch; the image's own storage comes from aligned_alloc, which is "
      "not counted) |\n",
      run.workloads.front().name.c_str(), scene.faces.size(), warm, fresh);
}

// The last row of the table. Tracing off: a tracer that selects no triangle costs its filter test
// per triangle; the no-op tracer costs nothing (machine code identical to a build without trace
// hooks: scripts/bench_tracer_overhead.sh).
void tracing_off(BenchRun& run) {
  const FillOptions gouraud{.shading = Shading::gouraud};
  const Scene& s = run.workloads.front().scene;
  std::vector<Job> trace_jobs{
      warm_render<Bgr8>("none", s, gouraud),
      {"filtered out",
       [&, image = std::make_shared<Bgr8Image>(), scratch = std::make_shared<RenderScratch>()] {
         trace::TraceFilter filter;
         filter.triangles = trace::IndexSet::parse("999999999");
         trace::EventTracer<trace::Recorder> tracer(
             trace::Recorder(trace::make_header(s.width, s.height, gouraud, filter.level)), filter);
         render(*image, s, gouraud, *scratch, tracer);
         Bench::sink(*image);
       }}};
  const std::vector<double> tt = bench::time_interleaved(trace_jobs, run.args.rounds);
  std::printf(
      "| tracing: a tracer selecting no triangle vs none | %.3f × | | the per-triangle "
      "filter test only |\n",
      tt[1] / tt[0]);
}

// Two cores: bands in parallel.
void parallel_render(BenchRun& run) {
  std::vector<Workload> par{
      run.workloads.front(),
      {"1200×1200, 25,000 triangles", bench::grid_mesh(5, 1200, 1200, 112, 112)}};
  std::printf("\n## Parallel render (bands of rows, bit-identical output)\n\n");
  std::printf(
      "| workload | shading | 1 thread ms | 2 threads ms | speed-up | identical |\n"
      "|---|---|---:|---:|---:|---|\n");
  for (const Workload& w : par)
    for (Visibility vis : {Visibility::painter, Visibility::zbuffer})
      for (Shading sh : {Shading::flat, Shading::gouraud}) {
        // The z-buffer's rows: the large scene, Gouraud, enough to show its speed-up.
        const bool large = w.name != run.workloads.front().name;
        if (vis == Visibility::zbuffer && (!large || sh == Shading::flat)) continue;
        const FillOptions opt{.shading = sh, .visibility = vis};
        std::vector<Job> jobs{warm_render<Bgr8>("1", w.scene, opt),
                              warm_render<Bgr8>("2", w.scene, opt, 2)};
        const std::vector<double> t = bench::time_interleaved(jobs, run.args.rounds);
        const bool same = render<Bgr8>(w.scene, opt) == render_parallel<Bgr8>(w.scene, opt, 2);
        const std::string shading =
            std::string(to_string(sh)) + (vis == Visibility::zbuffer ? ", z-buffer" : "");
        std::printf("| %s | %s | %.3f | %.3f | %.2f | %s |\n", w.name.c_str(), shading.c_str(),
                    t[0] * 1e3, t[1] * 1e3, t[0] / t[1], same ? "yes" : "**no**");
        if (large && sh == Shading::gouraud)
          run.targets.push_back({w.name + ", " + shading + ": parallel speed-up on 2 threads",
                                 t[0] / t[1], vis == Visibility::zbuffer ? "≥ 1.7" : "≥ 1.8",
                                 false});
      }
}

// The scenes of the occlusion table: that hide most of their faces, and that hide none (where
// only the bookkeeping is left to measure).
std::vector<Workload> occlusion_scenes(const BenchRun& run) {
  std::vector<Workload> scenes;
  if (run.course) scenes.push_back(run.workloads.front());
  const int n = run.args.quick ? 5000 : 25000, cells = run.args.quick ? 40 : 112;
  scenes.push_back({"1200², " + std::to_string(n) + " overlapping triangles",
                    bench::small_triangles(3, 1200, 1200, n, 125)});
  scenes.push_back({"built-in scene", demo_scene()});
  scenes.push_back(
      {"1200² grid mesh (nothing hidden)", bench::grid_mesh(5, 1200, 1200, cells, cells)});
  scenes.push_back({"1200² surface, one layer (nothing hidden)",
                    bench::surface_layers(6, 1200, 1200, cells, cells, 1)});
  scenes.push_back({"1200² surfaces stacked 3 deep",
                    bench::surface_layers(7, 1200, 1200, cells / 2, cells / 2, 3)});
  return scenes;
}

// Skipping what the scene hides: the painter's render near to far against far to near, and the
// default (Occlusion::automatic: the way occlusion_choice.hpp picks, its prediction included)
// against both; then the z-buffered render near to far against its scene order (8-bit image only).
void occlusion(BenchRun& run) {
  const std::vector<Workload> scenes = occlusion_scenes(run);
  std::printf(
      "\n## Skipping what the scene hides (near to far, what nearer faces cover is never "
      "drawn): near to far ÷ far to near, and the default's choice\n\n"
      "| workload | shading | image | far to near ms | near to far ms | ratio | default ms | "
      "default ÷ far to near | default chose | faces hidden | rejected before set-up | "
      "pixel writes clipped | identical |\n"
      "|---|---|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---|\n");
  for (const Workload& w : scenes)
    for (Shading sh : {Shading::flat, Shading::gouraud})
      for (int image : {0, 1, 2}) {  // 8-bit, float, 8-bit z-buffered
        const bool bytes = image != 1, zbuffer = image == 2;
        const Visibility vis = zbuffer ? Visibility::zbuffer : Visibility::painter;
        const FillOptions near{
            .shading = sh, .visibility = vis, .occlusion = Occlusion::near_to_far},
            far{.shading = sh, .visibility = vis, .occlusion = Occlusion::far_to_near},
            chosen{.shading = sh, .visibility = vis, .occlusion = Occlusion::automatic};
        std::vector<Job> jobs;
        if (bytes)
          jobs = {warm_render<Bgr8>("far", w.scene, far), warm_render<Bgr8>("near", w.scene, near),
                  warm_render<Bgr8>("default", w.scene, chosen)};
        else
          jobs = {warm_render<Rgb32f>("far", w.scene, far),
                  warm_render<Rgb32f>("near", w.scene, near),
                  warm_render<Rgb32f>("default", w.scene, chosen)};
        const std::vector<double> t = bench::time_interleaved(jobs, run.args.rounds);
        RenderStats st, chosen_st;
        const bool same =
            bytes ? render<Bgr8>(w.scene, near, &st) == render<Bgr8>(w.scene, far) &&
                        render<Bgr8>(w.scene, chosen, &chosen_st) == render<Bgr8>(w.scene, far)
                  : render<Rgb32f>(w.scene, near, &st) == render<Rgb32f>(w.scene, far) &&
                        render<Rgb32f>(w.scene, chosen, &chosen_st) == render<Rgb32f>(w.scene, far);
        const double share =
            st.triangles_hidden ? double(st.triangles_rejected) / st.triangles_hidden : 0;
        std::printf(
            "| %s | %s | %s | %.3f | %.3f | %.3f | %.3f | %.3f | %s | %lld | %lld (%.0f %%) | "
            "%lld | %s |\n",
            w.name.c_str(), to_string(sh),
            zbuffer ? "8-bit, z-buffer (scene order ÷ near to far)"
            : bytes ? "8-bit"
                    : "float",
            t[0] * 1e3, t[1] * 1e3, t[1] / t[0], t[2] * 1e3, t[2] / t[0], to_string(chosen_st.path),
            st.triangles_hidden, st.triangles_rejected, 100 * share, st.pixels_clipped,
            same ? "yes" : "**no**");
        const bool hides = w.name.find("nothing hidden") == std::string::npos;
        if (zbuffer) continue;  // the targets are set for the painter's order
        if (w.name == "course scene" && sh == Shading::flat && bytes) {
          run.targets.push_back(
              {"course scene, flat: near to far / far to near", t[1] / t[0], "≤ 0.5", false});
          run.targets.push_back(
              {"course scene: hidden faces rejected before set-up (share)", share, "≥ 0.8", false});
        }
        if (!hides && sh == Shading::flat && bytes)
          run.targets.push_back({w.name + ", flat: the default (the way it chooses) / far to near",
                                 t[2] / t[0], "≤ 1.05", false});
      }
}

// The one-shot command: `scantrace render` of a 1200² scene as a user runs it, a new process each
// time, against the same render warm in this process (the float canvas the command draws on,
// Gouraud, its default).
void one_shot_command(BenchRun& run) {
  const Scene grid = bench::grid_mesh(5, 1200, 1200, 112, 112);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("scantrace-bench-" + std::to_string(::getpid()));
  struct Remove {
    std::filesystem::path dir;
    ~Remove() {
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    }
  } remove{dir};
  std::filesystem::create_directories(dir);
  const std::string scene_file = (dir / "scene.json").string(), png = (dir / "out.png").string();
  save_scene(grid, scene_file);
  // `scantrace`, which users run and which renders itself, beside this `scantrace-tools`.
  const std::string self =
      (std::filesystem::read_symlink("/proc/self/exe").parent_path() / "scantrace").string();
  std::vector<Job> jobs{
      {"start-up",
       [&] {
         bench::run_child_seconds({self, "--version"});
       }},
      {"render",
       [&] {
         bench::run_child_seconds({self, "render", scene_file, "-o", png});
       }},
      {"render 2",
       [&] {
         bench::run_child_seconds({self, "render", scene_file, "-o", png, "--threads", "2"});
       }},
      warm_render<Rgb32f>("warm", grid, FillOptions{})};
  // A child run takes a fraction of a second: fewer rounds than the in-process tables.
  const std::vector<double> t = bench::time_interleaved(jobs, std::clamp(run.args.rounds, 3, 9));
  std::printf(
      "\n## The one-shot command: `scantrace render` of a 1200² scene (%zu faces), a new "
      "process per run\n\n| | median ms | ÷ the warm render |\n|---|---:|---:|\n",
      grid.faces.size());
  const char* names[] = {"start-up alone (`scantrace --version`)", "`scantrace render`",
                         "`scantrace render --threads 2`",
                         "the same render warm in this process (float canvas, Gouraud)"};
  for (int i = 0; i < 4; ++i)
    std::printf("| %s | %.2f | %.1f |\n", names[i], t[i] * 1e3, t[i] / t[3]);
  run.targets.push_back({"`scantrace render` of 1200², one process: time / the warm render's",
                         t[1] / t[3], "≤ 2", false});
  run.targets.push_back(
      {"`scantrace render --threads 2` / `--threads 1`", t[2] / t[1], "≤ 1", false});
}

// The sections of the report, in order: each measures its tables and adds its targets.
constexpr struct {
  const char* what;  // for the progress line
  void (*run)(BenchRun&);
} kSections[] = {
    {"every method on every workload", compare_methods},
    {"the half canvas against the memset limit", half_canvas_limit},
    {"the float canvas", float_canvas},
    {"what the fill skips", fill_skips},
    {"allocations per render", allocations},
    {"the cost of tracing off", tracing_off},
    {"the parallel render", parallel_render},
    {"skipping what the scene hides", occlusion},
    {"the one-shot command", one_shot_command},
};

void run_bench(const BenchArgs& args) {
  const bool course = !args.scene.empty() && std::filesystem::exists(args.scene);
  std::printf(
      "# scantrace bench\n\nMedians of %d interleaved rounds on this machine; every "
      "ratio compares times measured in the same run. 8-bit BGR images unless noted. "
      "Errors: every face filled alone in its 6 vertex orders and compared with the "
      "exact reference (OpenCV under its own closed rule).\n",
      args.rounds);
  if (args.scene.empty())
    std::printf("\n(No --scene given: the course scene rows are missing.)\n");
  else if (!course)
    std::printf("\n(%s not found: the course scene rows are missing.)\n", args.scene.c_str());

  BenchRun run{args, course, make_workloads(args, course), Bench(args), {}};
  for (const auto& section : kSections) {
    spdlog::info("bench: {}", section.what);
    section.run(run);
  }

  for (Target& t : run.targets) {
    const bool at_most = t.goal.rfind("≤", 0) == 0;
    const double goal = std::stod(t.goal.substr(t.goal.find(' ') + 1));
    t.met = at_most ? t.measured <= goal : t.measured >= goal;
  }
  print_targets(run.targets);

  const std::filesystem::path csv_path = args.prefix + ".csv", png_path = args.prefix + ".png";
  write_file_atomically(csv_path, bench::csv(run.bench.rows()));
  bench::write_plot(run.bench.rows(), png_path);
  std::printf("\nWrote %s and %s.\n", csv_path.c_str(), png_path.c_str());
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "The runtime-vs-error benchmark. For each fill method (exact, float, double,\n"
      "halfspace), flat and Gouraud, and for OpenCV's cv::fillConvexPoly (flat only,\n"
      "same triangles, same painter's order, same 8-bit image, same process), on the\n"
      "course scene (when --scene exists), the built-in scene, small random\n"
      "triangles, one triangle covering half of a 4096x4096 canvas and a triangle\n"
      "with a vertex at -1e9: median time, triangles/s, pixels/s, coverage errors\n"
      "and colour error against the exact reference, and the physical limit (the\n"
      "same pixels stored at memcpy speed; for the half canvas also memset of a\n"
      "one-byte value, faster still). Then the float canvas, what the fill\n"
      "skips (off-canvas, zero-area, equal-colour Gouraud, allocations, tracing\n"
      "off), the parallel render, `scantrace render` of a 1200x1200 scene as a new\n"
      "process per run (what a user waits for) against the same render warm, and the\n"
      "targets met or not. Renders reuse their image, as OpenCV's reuses its Mat.\n"
      "Jobs of one table run interleaved, round after round, and report medians, so\n"
      "their ratios hold on a noisy machine. Markdown on stdout, PREFIX.csv and\n"
      "PREFIX.png (time against error, log scales). Progress on stderr.");
  cmd->add_option("--scene", args->scene,
                  "the course scene, e.g. ../shared/data/hw1_2024.json (its rows are skipped\n"
                  "without it, or when the file does not exist)");
  cmd->add_option("--rounds", args->rounds, "interleaved rounds per table (medians of these)")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_flag("--quick", args->quick,
                "smaller workloads (2,000 small triangles, a 1024² canvas for the half-canvas\n"
                "triangle, whose accuracy is then not checked) for a fast look");
  cmd->add_option("-o,--output", args->prefix, "prefix of the CSV and PNG outputs")
      ->capture_default_str();
  return {cmd, [args] { run_bench(*args); }};
}

}  // namespace scantrace::cli
