// The triangle sweep (src/fast/triangle_sweep.hpp) sets a triangle's two runs up without an edge
// table; the general sweep (src/scanline_sweep.hpp) builds the table and orders the active edges
// by their exact crossings. The fill takes the triangle sweep for an untraced triangle and the
// general one for a traced triangle, so a tracer that only asks for triangles makes the same fill
// go the general way. Both must give the same pixels, the same colours to the last bit and the
// same counts, in particular where the triangle sweep decides something the general sweep
// decides differently: vertices exactly on rows and pixel centres, flat tops and bottoms, bands
// that begin or end inside either run, and vertices far off the canvas.
#include <catch2/catch.hpp>

#include <vector>

#include "reference_raster.hpp"
#include "src/scanline_fill.hpp"
#include "src/splitmix64.hpp"

using namespace scantrace;

namespace {

// The colours the fill hands over, kept in double (before any pixel format could round away a
// difference), for the rows of one band.
struct BandColorCanvas {
  int w, h;
  RowBand band;
  std::vector<Color> pixels;
  std::vector<int> writes;
  BandColorCanvas(int width, int height, RowBand b)
      : w(width), h(height), band(b), pixels(width * height), writes(width * height, 0) {}
  int width() const { return w; }
  int height() const { return h; }
  RowBand rows() const { return band; }
  void set(int x, int y, Color c) { pixels[y * w + x] = c, ++writes[y * w + x]; }
  void fill_span(int y, int xb, int xe, Color c) {
    for (int x = xb; x < xe; ++x) set(x, y, c);
  }
};

// Wants every triangle and nothing finer: the fill then sweeps the edge table (a traced triangle
// shows its edge events) and the tracer sees no rows.
struct TriangleOnlyTracer {
  static constexpr TraceLevel max_level = TraceLevel::triangle;
  int begun = 0;
  bool wants_triangle(int) const { return true; }
  void triangle_begin(const PolygonSetup&) { ++begun; }
  void edge_table(const EdgeTableView&) {}
  void triangle_end(int, i64, i64) {}
  void triangle_skipped(int, SkipReason) {}
};

// A coordinate on a coarse grid (whole and half pixels, so vertices land on rows and on pixel
// centres, and several share a y) or anywhere, from a bit further out than the canvas.
double coordinate(SplitMix64& rng, bool coarse, double lo, double hi) {
  const double v = rng.uniform(lo, hi);
  return coarse ? std::floor(v * 2) / 2 + (rng.next() % 4 == 0 ? 0.5 : 0.0) : v;
}

}  // namespace

TEST_CASE("triangle sweep: the same pixels, colours and counts as the edge table's sweep",
          "[triangle_sweep]") {
  SplitMix64 rng(20261125);
  constexpr int W = 40, H = 40;
  int compared = 0, with_pixels = 0, traced = 0;
  for (int i = 0; i < 4000; ++i) {
    const bool coarse = i % 2 == 0;
    std::array<Vec2, 3> v;
    for (Vec2& p : v) p = {coordinate(rng, coarse, -8, W + 8), coordinate(rng, coarse, -8, H + 8)};
    if (i % 5 == 0) v[1].y = v[0].y;     // a flat top or bottom
    if (i % 97 == 0) v[2].x = -1e9 + i;  // a vertex a billion pixels away
    const std::array<Color, 3> colors{Color{rng.uniform(0, 1), rng.uniform(0, 1), 0.25},
                                      Color{rng.uniform(0, 1), 0.5, rng.uniform(0, 1)},
                                      Color{1.0 / 3.0, rng.uniform(0, 1), rng.uniform(0, 1)}};
    // A band that may begin or end inside either run (one band in three is the whole canvas).
    const int a = static_cast<int>(rng.next() % (H + 1)),
              b = static_cast<int>(rng.next() % (H + 1));
    const RowBand band = i % 3 == 0 ? RowBand{0, H} : RowBand{std::min(a, b), std::max(a, b)};
    for (Shading shading : {Shading::flat, Shading::gouraud}) {
      const FillOptions opt{.shading = shading};
      BandColorCanvas fast(W, H, band), general(W, H, band);
      FillScratch s1, s2;
      const PolygonInput in{v, colors, 0, std::nullopt};
      const FillResult r1 = fill_polygon(fast, in, opt, s1);
      TriangleOnlyTracer tracer;
      const FillResult r2 = fill_polygon(general, in, opt, s2, tracer);
      traced += tracer.begun;
      INFO("triangle " << i << " (" << v[0].x << "," << v[0].y << ") (" << v[1].x << "," << v[1].y
                       << ") (" << v[2].x << "," << v[2].y << "), rows " << band.begin << "…"
                       << band.end << ", " << to_string(shading));
      REQUIRE(r1.skipped == r2.skipped);
      REQUIRE(r1.rows == r2.rows);
      REQUIRE(r1.pixels == r2.pixels);
      REQUIRE(fast.writes == general.writes);
      for (int p = 0; p < W * H; ++p)
        if (fast.writes[p]) REQUIRE(fast.pixels[p] == general.pixels[p]);
      ++compared;
      if (r1.pixels > 0) ++with_pixels;
      // Independently of either sweep: the whole-canvas fills cover the exact reference's pixels.
      if (band.begin == 0 && band.end == H && i % 97 != 0) {
        const auto ref = sttest::ref_rasterize(W, H, v, colors, FillRule::top_left);
        for (int y = 0; y < H; ++y)
          for (int x = 0; x < W; ++x) REQUIRE(ref.at(x, y) == (fast.writes[y * W + x] == 1));
      }
    }
  }
  // The general sweep really ran (every set-up triangle traced), and most cases drew something.
  CHECK(traced > 0);
  CHECK(with_pixels > compared / 2);
}
