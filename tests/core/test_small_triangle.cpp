// The small-triangle spans (src/fast/small_triangle.hpp): the half-space test in 32-bit SIMD lanes must
// give every row exactly the pixels the exact reference covers, with every Highway target's
// kernel this CPU can run, on every grid the fill supports — including boxes whose edge functions
// come close to the 32-bit limit, where a set-up that let a larger triangle in would wrap around.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "random.hpp"
#include "reference_raster.hpp"
#include "src/band_render.hpp"
#include "src/fill_setup.hpp"
#include "src/flat_color.hpp"
#include "src/fast/small_triangle.hpp"
#include "src/fast/small_triangle_batch.hpp"

using namespace scantrace;

namespace {

constexpr int W = 56, H = 56;

// A triangle in a box of up to `size` pixels somewhere around the canvas (partly off it at times),
// its vertices on whole and half pixels in one case of two: centres on edges and vertices.
std::array<Vec2, 3> random_triangle(sttest::Rng& rng, double size) {
  const Vec2 corner = rng.point(-10, W + 2, -10, H + 2);
  std::array<Vec2, 3> v;
  const bool coarse = rng.next() % 2 == 0;
  for (Vec2& p : v) {
    p = {corner.x + rng.uniform(0, size), corner.y + rng.uniform(0, 4 * size)};
    if (coarse) p = {std::round(p.x * 2) / 2, std::round(p.y * 2) / 2};
  }
  if (rng.next() % 6 == 0) v[1].y = v[0].y;  // a flat top or bottom
  return v;
}

}  // namespace

TEST_CASE("small triangles: every row's span is the exact reference's, on every SIMD target",
          "[core][simd][small_triangle]") {
  const auto kernels = small_triangle_kernels();
  REQUIRE(!kernels.empty());
#if defined(__x86_64__)
  CHECK(kernels.size() >= 2);  // SSSE3 or better, and the portable kernel
#endif
  for (const auto& kernel : kernels) {
    INFO("Highway target " << kernel.target);
    sttest::Rng rng(20261125);
    int taken = 0, declined = 0, near_limit = 0;
    long long pixels = 0;
    for (int i = 0; i < 16000; ++i) {
      const int bits = std::array{0, 4, 8, 12}[i % 4];
      // Sizes from slivers to boxes the set-up must refuse (wider than 32 columns, or too large
      // for 32 bits on the finest grid).
      const double size = std::array{0.7, 3.0, 9.0, 24.0, 40.0}[(i / 4) % 5];
      const std::array<Vec2, 3> v = random_triangle(rng, size);
      const SubpixelGrid grid(bits);
      const std::array<FixedPoint, 3> p{grid.snap(v[0]), grid.snap(v[1]), grid.snap(v[2])};
      const i64 cross =
          (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
      if (cross == 0) continue;
      const int a = static_cast<int>(rng.next() % (H + 1)),
                b = static_cast<int>(rng.next() % (H + 1));
      const RowBand band = i % 3 == 0 ? RowBand{0, H} : RowBand{std::min(a, b), std::max(a, b)};
      const GridBox box = grid_box(p, grid, FillRule::top_left);
      SmallTriangle t;
      if (!small_triangle(p, box, cross > 0, grid, W, band, t)) {
        ++declined;
        continue;
      }
      ++taken;
      // How close the lanes' edge functions may come to 2^31 (the set-up's own bound).
      const i64 dx = box.x_max - box.x_min, dy = box.y_max - box.y_min, s = grid.scale();
      if (dy * (dx + 2 * kSmallTriangleLanes * s) + dx * (dy + 2 * s) > (i64{1} << 29))
        ++near_limit;

      const sttest::RefRaster ref =
          sttest::ref_rasterize(W, H, v, std::array<Color, 3>{Color{}, Color{}, Color{}},
                                sttest::RefRule::top_left, bits);
      std::vector<RowSpan> spans(static_cast<std::size_t>(t.rows) + 1, RowSpan{-7, -7});
      kernel.function(t, spans.data());
      REQUIRE(spans.back().begin == -7);  // nothing written past the box's rows
      for (int y = band.begin; y < band.end; ++y) {
        int first = W, last = -1, count = 0;
        for (int x = 0; x < W; ++x)
          if (ref.at(x, y)) first = std::min(first, x), last = std::max(last, x), ++count;
        const bool in_box = y >= t.row0 && y < t.row0 + t.rows;
        INFO("triangle " << i << " (" << v[0].x << "," << v[0].y << ") (" << v[1].x << "," << v[1].y
                         << ") (" << v[2].x << "," << v[2].y << "), grid bits " << bits << ", row "
                         << y);
        if (!in_box) {
          REQUIRE(count == 0);  // the box holds every covered row of the band
          continue;
        }
        const RowSpan got = spans[static_cast<std::size_t>(y - t.row0)];
        if (count == 0) {
          REQUIRE(got.begin >= got.end);
        } else {
          REQUIRE(last - first + 1 == count);  // one run per row: the reference agrees it is convex
          REQUIRE(got.begin == first);
          REQUIRE(got.end == last + 1);
          pixels += count;
        }
      }
    }
    // Both sides of the set-up's limits were exercised, and many boxes came near the 32-bit one.
    UNSCOPED_INFO("taken " << taken << ", declined " << declined << ", near the limit "
                           << near_limit << ", pixels " << pixels);
    CHECK(taken > 3000);
    CHECK(declined > 1000);
    CHECK(near_limit > 150);
    CHECK(pixels > 100000);
  }
}

TEST_CASE("small triangles: the set-up refuses what the kernel cannot do exactly",
          "[core][small_triangle]") {
  const SubpixelGrid grid(8);
  SmallTriangle t;
  const auto setup = [&](std::array<Vec2, 3> v, int width = 512, RowBand band = {0, 512}) {
    const std::array<FixedPoint, 3> p{grid.snap(v[0]), grid.snap(v[1]), grid.snap(v[2])};
    const i64 cross = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
    return small_triangle(p, grid_box(p, grid, FillRule::top_left), cross > 0, grid, width, band,
                          t);
  };
  CHECK(setup({Vec2{10, 10}, Vec2{20, 12}, Vec2{12, 30}}));
  CHECK(t.col0 == 10);
  CHECK(t.cols == 10);  // columns 10 … 19: a centre at x = 20 is the right end, never inside
  CHECK(t.row0 == 10);
  CHECK(t.rows == 20);
  // 32 columns are taken, 33 are not; 128 rows are taken, 129 are not.
  CHECK(setup({Vec2{0.5, 0}, Vec2{32.5, 1}, Vec2{1, 3}}));
  CHECK_FALSE(setup({Vec2{0.5, 0}, Vec2{33.5, 1}, Vec2{1, 3}}));
  CHECK(setup({Vec2{0, 0.5}, Vec2{1, 128.5}, Vec2{3, 1}}));
  CHECK_FALSE(setup({Vec2{0, 0.5}, Vec2{1, 129.5}, Vec2{3, 1}}));
  // A large triangle whose part on the canvas is a small box: its edge functions are not small.
  CHECK_FALSE(setup({Vec2{-5000, 3}, Vec2{10, 2}, Vec2{9, 9}}));
  // Nothing of the box on the canvas or in the band.
  CHECK_FALSE(setup({Vec2{600, 3}, Vec2{610, 2}, Vec2{609, 9}}));
  CHECK_FALSE(setup({Vec2{10, 10}, Vec2{20, 12}, Vec2{12, 30}}, 512, RowBand{40, 80}));
}

namespace {

// A batch of random faces: sizes from under a pixel to 40, one in 16 with zero area, one in 16
// with a coordinate out of range (huge, NaN or infinite), one in 16 whose box reaches far off
// the canvas; colours partly outside [0, 1] and now and then NaN.
struct RandomBatch {
  TriangleBatch in{};
  std::array<std::array<Vec2, 3>, kTriangleBatch> v;
  std::array<std::array<Color, 3>, kTriangleBatch> c;
};

RandomBatch random_batch(sttest::Rng& rng) {
  RandomBatch r;
  for (int k = 0; k < kTriangleBatch; ++k) {
    const double size = std::array{0.7, 3.0, 9.0, 24.0, 40.0}[rng.next() % 5];
    r.v[k] = random_triangle(rng, size);
    switch (rng.next() % 16) {
      case 0:
        r.v[k][2] = r.v[k][0];  // zero area
        break;
      case 1:
        r.v[k][1].x = std::array<double, 4>{1e10, -2e9, std::nan(""), HUGE_VAL}[rng.next() % 4];
        break;
      case 2:
        r.v[k][0] = {r.v[k][0].x - 3000, r.v[k][0].y};  // a large box reaching the canvas
        break;
      default:
        break;
    }
    for (Color& col : r.c[k])
      col = {rng.uniform(-0.2, 1.2), rng.uniform(0, 1),
             rng.next() % 50 == 0 ? std::nan("") : rng.uniform(0, 1)};
    for (int i = 0; i < 3; ++i) {
      r.in.x[i][k] = r.v[k][i].x, r.in.y[i][k] = r.v[k][i].y;
      r.in.r[i][k] = r.c[k][i].r, r.in.g[i][k] = r.c[k][i].g, r.in.b[i][k] = r.c[k][i].b;
    }
  }
  return r;
}

struct DecisionTally {
  int taken = 0, declined = 0, culled = 0, degenerate = 0, out_of_range = 0;
};

// The scalar decision for one face, step by step in fill_polygon's order; when it takes the face,
// its snapped vertices and small_triangle's set-up are in p and t.
bool scalar_takes(const std::array<Vec2, 3>& v, const SubpixelGrid& grid, const BatchTarget& target,
                  std::array<FixedPoint, 3>& p, SmallTriangle& t, DecisionTally& tally) {
  if (!std::all_of(v.begin(), v.end(), SubpixelGrid::representable)) {
    ++tally.out_of_range;
    return false;
  }
  for (int i = 0; i < 3; ++i) p[i] = grid.snap(v[i]);
  const i128 area2 = static_cast<i128>(p[1].x - p[0].x) * (p[2].y - p[0].y) -
                     static_cast<i128>(p[2].x - p[0].x) * (p[1].y - p[0].y);
  if (area2 == 0) {
    ++tally.degenerate;
    return false;
  }
  if (target.cull != Cull::none && (target.cull == Cull::back ? area2 > 0 : area2 < 0)) {
    ++tally.culled;
    return false;
  }
  const GridBox box = grid_box(p, grid, FillRule::top_left);
  return covers_pixels(box, W, target.band) == SkipReason::none &&
         small_triangle(p, box, area2 > 0, grid, W, target.band, t);
}

}  // namespace

// The batched set-up (src/fast/small_triangle_batch.hpp) against the scalar one it stands in for, face
// by face: the same decision (fill_polygon's checks in its order: representable, a non-zero area,
// not culled, a pixel of the canvas and band, small_triangle's limits), and for a face it takes
// the same edge functions, box and flat colour, bit for bit, with every Highway target's kernel.
TEST_CASE("small triangles: the batched set-up is the scalar one, on every SIMD target",
          "[core][simd][small_triangle]") {
  const auto kernels = small_triangle_batch_kernels();
  REQUIRE(!kernels.empty());
  for (const auto& kernel : kernels) {
    INFO("Highway target " << kernel.target);
    sttest::Rng rng(20261126);
    DecisionTally tally;
    std::vector<int> order;
    for (int batch = 0; batch < 4000; ++batch) {
      const int bits = std::array{0, 4, 8, 12}[batch % 4];
      const SubpixelGrid grid(bits);
      const int a = static_cast<int>(rng.next() % (H + 1)),
                b = static_cast<int>(rng.next() % (H + 1));
      const RowBand band = batch % 3 == 0 ? RowBand{0, H} : RowBand{std::min(a, b), std::max(a, b)};
      const Cull cull = std::array{Cull::none, Cull::back, Cull::front}[(batch / 4) % 3];
      const BatchTarget target{bits, W, band, cull};
      const RandomBatch faces = random_batch(rng);
      BatchSetup out;
      kernel.function(faces.in, target, out);
      for (int k = 0; k < kTriangleBatch; ++k) {
        const auto& v = faces.v[k];
        INFO("batch " << batch << " face " << k << " (" << v[0].x << "," << v[0].y << ") ("
                      << v[1].x << "," << v[1].y << ") (" << v[2].x << "," << v[2].y
                      << "), grid bits " << bits);
        std::array<FixedPoint, 3> p{};
        SmallTriangle t;
        const bool small = scalar_takes(v, grid, target, p, t, tally);
        REQUIRE((out.small[k] != 0) == small);
        if (!small) {
          ++tally.declined;
          continue;
        }
        ++tally.taken;
        CHECK(out.triangle(k) == t);
        const Color want = flat_color(p, faces.c[k], order), flat = out.flat(k);
        for (const auto& [w, g] : {std::pair{want.r, flat.r}, {want.g, flat.g}, {want.b, flat.b}})
          CHECK(std::bit_cast<std::uint64_t>(w) == std::bit_cast<std::uint64_t>(g));
      }
    }
    UNSCOPED_INFO("taken " << tally.taken << ", declined " << tally.declined << " (culled "
                           << tally.culled << ", zero area " << tally.degenerate
                           << ", out of range " << tally.out_of_range << ")");
    CHECK(tally.taken > 4000);
    CHECK(tally.declined > 8000);
    CHECK(tally.culled > 1000);
    CHECK(tally.degenerate > 1000);
    CHECK(tally.out_of_range > 1000);
  }
}

namespace {

// A tracer at the triangle level that selects no triangle: the fill then runs face by face through
// fill_polygon, as before the batched set-up, and draws what the untraced render draws (the
// trace contract: tracing never changes a pixel).
struct SelectsNoTriangle {
  static constexpr TraceLevel max_level = TraceLevel::triangle;
  bool wants_triangle(int) { return false; }
  void triangle_begin(const PolygonSetup&) {}
  void edge_table(const EdgeTableView&) {}
  void triangle_end(int, i64, i64) {}
  void triangle_skipped(int, SkipReason) {}
};

// A soup of `count` triangles over a 300 × 200 canvas, from slivers to 60-pixel boxes, with some
// of zero area, some out of range and some reaching far off the canvas; depths at random.
Scene soup(std::uint64_t seed, int count) {
  sttest::Rng rng(seed);
  Scene s;
  s.width = 300, s.height = 200;
  for (int f = 0; f < count; ++f) {
    const double size = std::array{0.6, 3.0, 8.0, 20.0, 60.0}[rng.next() % 5];
    const Vec2 corner = rng.point(-20, 310, -20, 210);
    const int base = static_cast<int>(s.vertices.size());
    for (int i = 0; i < 3; ++i) {
      s.vertices.push_back({corner.x + rng.uniform(0, size), corner.y + rng.uniform(0, size)});
      s.vcolors.push_back(rng.color());
      s.depth.push_back(rng.uniform(0, 10));
    }
    switch (rng.next() % 20) {
      case 0:
        s.vertices[base + 2] = s.vertices[base];  // zero area
        break;
      case 1:
        s.vertices[base + 1].x = 5e9;  // out of range: skipped
        break;
      case 2:
        s.vertices[base].x -= 4000;  // a large box reaching the canvas
        break;
      default:
        break;
    }
    s.faces.push_back({base, base + 1, base + 2});
  }
  return s;
}

}  // namespace

// The face loop with the batched set-up (painter.hpp, fill_faces) against the loop it replaces,
// face by face: the same image and the same counts, far to near and near to far, painter's and
// z-buffered, on the 8-bit and the float canvas, culled or not, on several grids and in bands.
TEST_CASE("small triangles: the batched face loop draws what the face-by-face loop draws",
          "[core][small_triangle]") {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    const Scene scene = soup(seed, 3000);
    for (const int bits : {0, 4, 8})
      for (const Cull cull : {Cull::none, Cull::back, Cull::front})
        for (const Visibility visibility : {Visibility::painter, Visibility::zbuffer}) {
          INFO("seed " << seed << ", subpixel bits " << bits << ", cull " << static_cast<int>(cull)
                       << (visibility == Visibility::zbuffer ? ", z-buffered" : ""));
          FillOptions opt;
          opt.shading = Shading::flat;
          opt.subpixel_bits = bits;
          opt.cull = cull;
          opt.visibility = visibility;
          opt.occlusion = Occlusion::far_to_near;
          REQUIRE(detail::batchable(opt));
          SelectsNoTriangle tracer;
          RenderStats want_stats, got_stats;
          const Image<Bgr8> want = render<Bgr8>(scene, opt, tracer, &want_stats);
          CHECK(render<Bgr8>(scene, opt, &got_stats) == want);
          CHECK(got_stats.triangles_filled == want_stats.triangles_filled);
          CHECK(got_stats.triangles_culled == want_stats.triangles_culled);
          CHECK(got_stats.triangles_skipped == want_stats.triangles_skipped);
          CHECK(got_stats.pixels == want_stats.pixels);
          CHECK(render<Rgb32f>(scene, opt) == render<Rgb32f>(scene, opt, tracer));
          CHECK(render_parallel<Bgr8>(scene, opt, 3) == want);
          FillOptions near = opt;
          near.occlusion = Occlusion::near_to_far;
          CHECK(render<Bgr8>(scene, near) == want);
          CHECK(render_parallel<Bgr8>(scene, near, 3) == want);
          // Near to far, what was rejected before set-up (hidden) and what was drawn, against the
          // same faces drawn Gouraud with one colour each, which is not batched: the counts
          // depend on coverage and depth only.
          Scene one_colour = scene;
          for (std::size_t v = 0; v + 2 < one_colour.vcolors.size(); v += 3)
            one_colour.vcolors[v + 1] = one_colour.vcolors[v + 2] = one_colour.vcolors[v];
          FillOptions gouraud = near;
          gouraud.shading = Shading::gouraud;
          RenderStats batched, unbatched;
          render<Bgr8>(one_colour, near, &batched);
          render<Bgr8>(one_colour, gouraud, &unbatched);
          CHECK(batched.triangles_hidden == unbatched.triangles_hidden);
          CHECK(batched.triangles_rejected == unbatched.triangles_rejected);
          CHECK(batched.triangles_filled == unbatched.triangles_filled);
          CHECK(batched.pixels == unbatched.pixels);
          CHECK(batched.triangles_hidden > 0);
        }
  }
}
