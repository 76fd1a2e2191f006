// Microbenchmarks of the fill's kernels (Google Benchmark, medians of repetitions): what one
// triangle costs before any row (set-up and rejection), per row of a thin triangle, and per pixel
// of long flat and Gouraud spans, on the 8-bit and float canvases. docs/performance.md explains the
// numbers.
//
//   build/bench/bench_kernels [--benchmark_filter=REGEX]
#include <benchmark/benchmark.h>

#include <array>
#include <cstring>
#include <vector>

#include "src/scanline_fill.hpp"

namespace {

using namespace scantrace;

template <class P>
void fill_one(benchmark::State& state, const std::array<Vec2, 3>& v, Shading shading, int size) {
  Image<P> image(size, size);
  ImageCanvas<P> canvas(image);
  FillScratch scratch;
  const std::array<Color, 3> c{Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
  const FillOptions opt{.shading = shading};
  long long pixels = 0;
  for (auto _ : state) {
    pixels += fill_polygon(canvas, PolygonInput{v, c, 0, std::nullopt}, opt, scratch).pixels;
    benchmark::DoNotOptimize(image.row(0));
    benchmark::ClobberMemory();
  }
  state.counters["pixels/s"] =
      benchmark::Counter(static_cast<double>(pixels), benchmark::Counter::kIsRate);
}

// Rejected before any row: off the canvas, and zero area after snapping.
void offscreen(benchmark::State& s) {
  fill_one<Bgr8>(s, {Vec2{-40, 10}, Vec2{-10, 17}, Vec2{-25, 30}}, Shading::gouraud, 512);
}
void zero_area(benchmark::State& s) {
  fill_one<Bgr8>(s, {Vec2{10, 10}, Vec2{200, 60}, Vec2{390, 110}}, Shading::gouraud, 512);
}
// The course scene's typical face: about 20 pixels over 16 rows.
void small_flat(benchmark::State& s) {
  fill_one<Bgr8>(s, {Vec2{100.3, 100.2}, Vec2{104.6, 108.9}, Vec2{101.1, 116.4}}, Shading::flat,
                 512);
}
void small_gouraud(benchmark::State& s) {
  fill_one<Bgr8>(s, {Vec2{100.3, 100.2}, Vec2{104.6, 108.9}, Vec2{101.1, 116.4}}, Shading::gouraud,
                 512);
}
// Per row: a sliver one pixel wide and 2,000 rows tall.
void sliver_rows(benchmark::State& s) {
  fill_one<Bgr8>(s, {Vec2{10.5, 0}, Vec2{11.5, 0}, Vec2{11, 2000}}, Shading::flat, 2048);
}
// Per pixel: half of a 2048² canvas, flat and Gouraud, 8-bit and float.
template <class P>
void half_canvas(benchmark::State& s, Shading shading) {
  fill_one<P>(s, {Vec2{0, 0}, Vec2{2048, 0}, Vec2{0, 2048}}, shading, 2048);
}
void half_bgr8_flat(benchmark::State& s) {
  half_canvas<Bgr8>(s, Shading::flat);
}
void half_bgr8_gouraud(benchmark::State& s) {
  half_canvas<Bgr8>(s, Shading::gouraud);
}
void half_float_flat(benchmark::State& s) {
  half_canvas<Rgb32f>(s, Shading::flat);
}
void half_float_gouraud(benchmark::State& s) {
  half_canvas<Rgb32f>(s, Shading::gouraud);
}
void memset_limit(benchmark::State& state) {
  std::vector<unsigned char> buf(2048 * 2048 / 2 * 3);
  for (auto _ : state) {
    std::memset(buf.data(), 200, buf.size());
    benchmark::DoNotOptimize(buf.data());
    benchmark::ClobberMemory();
  }
  state.counters["pixels/s"] =
      benchmark::Counter(2048.0 * 2048 / 2, benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK(offscreen);
BENCHMARK(zero_area);
BENCHMARK(small_flat);
BENCHMARK(small_gouraud);
BENCHMARK(sliver_rows);
BENCHMARK(half_bgr8_flat)->Unit(benchmark::kMicrosecond);
BENCHMARK(half_bgr8_gouraud)->Unit(benchmark::kMicrosecond);
BENCHMARK(half_float_flat)->Unit(benchmark::kMicrosecond);
BENCHMARK(half_float_gouraud)->Unit(benchmark::kMicrosecond);
BENCHMARK(memset_limit)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
