// The fill on arbitrary input: 3–6 vertices drawn from extreme, non-finite and ordinary values,
// colours anywhere, any canvas up to kMaxSide², every method, rule, shading and subpixel grid.
// Checked beyond "no crash": every write lies on the canvas; under the top-left rule no pixel of
// one triangle is written twice; and the two exact methods (edge table, half-space) cover the
// same pixels of a triangle. Polygons only get the first check: the fill's contract is convex
// polygons, and an arbitrary point list is not one (the half-space method fans it into triangles,
// which then overlap).
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

#include "src/scanline_fill.hpp"

namespace {

using namespace scantrace;

constexpr int kMaxSide = 512;

class CheckingCanvas {
 public:
  CheckingCanvas(int w, int h) : w_(w), h_(h), writes_(static_cast<std::size_t>(w) * h, 0) {}
  int width() const { return w_; }
  int height() const { return h_; }
  void fill_span(int y, int x_begin, int x_end, Color) {
    if (y < 0 || y >= h_ || x_begin < 0 || x_end > w_ || x_begin > x_end) __builtin_trap();
    for (int x = x_begin; x < x_end; ++x) ++writes_[index(x, y)];
  }
  void set(int x, int y, Color) {
    if (x < 0 || x >= w_ || y < 0 || y >= h_) __builtin_trap();
    ++writes_[index(x, y)];
  }
  const std::vector<std::uint8_t>& writes() const { return writes_; }

 private:
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * w_ + x; }
  int w_, h_;
  std::vector<std::uint8_t> writes_;
};

double coordinate(FuzzedDataProvider& in) {
  constexpr double kSpecial[] = {0.0,
                                 -0.0,
                                 0.5,
                                 -0.5,
                                 1e9,
                                 -1e9,
                                 1e300,
                                 -1e300,
                                 std::numeric_limits<double>::denorm_min(),
                                 std::numeric_limits<double>::max(),
                                 std::numeric_limits<double>::lowest(),
                                 std::numeric_limits<double>::infinity(),
                                 -std::numeric_limits<double>::infinity(),
                                 std::numeric_limits<double>::quiet_NaN()};
  switch (in.ConsumeIntegralInRange<int>(0, 3)) {
    case 0:
      return kSpecial[in.ConsumeIntegralInRange<std::size_t>(0, std::size(kSpecial) - 1)];
    case 1:
      return in.ConsumeIntegralInRange<int>(-64, kMaxSide + 64);
    case 2:
      return in.ConsumeIntegralInRange<int>(-64 * 256, (kMaxSide + 64) * 256) / 256.0;
    default:
      return in.ConsumeFloatingPoint<double>();
  }
}

double component(FuzzedDataProvider& in) {
  return in.ConsumeBool() ? in.ConsumeProbability<double>() : in.ConsumeFloatingPoint<double>();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const int width = in.ConsumeIntegralInRange<int>(1, kMaxSide);
  const int height = in.ConsumeIntegralInRange<int>(1, kMaxSide);
  FillOptions opt;
  opt.shading = in.ConsumeBool() ? Shading::flat : Shading::gouraud;
  opt.fill_rule = in.ConsumeBool() ? FillRule::closed : FillRule::top_left;
  opt.subpixel_bits = in.ConsumeIntegralInRange<int>(0, kMaxSubpixelBits);
  opt.method = static_cast<Method>(in.ConsumeIntegralInRange<int>(0, 3));
  const std::size_t n = in.ConsumeBool() ? 3 : in.ConsumeIntegralInRange<std::size_t>(4, 6);
  std::vector<Vec2> points(n);
  std::vector<Color> colors(n);
  for (std::size_t i = 0; i < n; ++i) {
    points[i] = {coordinate(in), coordinate(in)};
    colors[i] = {component(in), component(in), component(in)};
  }

  // SCANTRACE_FUZZ_PRINT=1 fuzz_fill CRASH prints the decoded input, to turn it into a test.
  if (std::getenv("SCANTRACE_FUZZ_PRINT")) {
    std::printf("canvas %dx%d shading %s rule %s bits %d method %s\n", width, height,
                to_string(opt.shading), to_string(opt.fill_rule), opt.subpixel_bits,
                to_string(opt.method));
    for (std::size_t i = 0; i < n; ++i)
      std::printf("  v%zu (%.17g, %.17g) colour (%.17g, %.17g, %.17g)\n", i, points[i].x,
                  points[i].y, colors[i].r, colors[i].g, colors[i].b);
    std::fflush(stdout);
  }

  CheckingCanvas canvas(width, height);
  FillScratch scratch;
  const PolygonInput polygon{points, colors, 0, std::nullopt};
  const FillResult r = fill_polygon(canvas, polygon, opt, scratch);
  if (r.pixels < 0) __builtin_trap();
  if (n > 3) return 0;  // see above: polygons are checked for staying on the canvas only
  if (r.pixels > static_cast<long long>(width) * height) __builtin_trap();

  // The float method may legitimately differ; the exact ones may not, for a triangle.
  if ((opt.method == Method::exact || opt.method == Method::halfspace)) {
    CheckingCanvas other(width, height);
    FillOptions other_opt = opt;
    other_opt.method = opt.method == Method::exact ? Method::halfspace : Method::exact;
    fill_polygon(other, polygon, other_opt, scratch);
    if (other.writes() != canvas.writes()) __builtin_trap();
  }
  if (opt.fill_rule == FillRule::top_left)
    for (std::uint8_t w : canvas.writes())
      if (w > 1) __builtin_trap();
  return 0;
}
