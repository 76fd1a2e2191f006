// A Gouraud triangle whose three vertex colours are equal is filled as a flat one: every covered
// pixel holds exactly that colour (not a colour interpolated to within rounding of it), and the
// coverage is the exact reference's.
#include <catch2/catch.hpp>

#include "reference_raster.hpp"
#include "src/scanline_fill.hpp"
#include "src/splitmix64.hpp"

using namespace scantrace;

namespace {

// Keeps the colours the fill hands over in double, so that "exactly that colour" is tested on
// the fill's own values, before any conversion to a pixel format could round a difference away.
struct ColorCanvas {
  int w, h;
  std::vector<Color> pixels;
  std::vector<char> written;
  ColorCanvas(int width, int height)
      : w(width), h(height), pixels(width * height), written(width * height, 0) {}
  int width() const { return w; }
  int height() const { return h; }
  void set(int x, int y, Color c) { pixels[y * w + x] = c, written[y * w + x] = 1; }
  void fill_span(int y, int xb, int xe, Color c) {
    for (int x = xb; x < xe; ++x) set(x, y, c);
  }
};

}  // namespace

TEST_CASE("uniform Gouraud: equal vertex colours fill exactly that colour", "[uniform]") {
  SplitMix64 rng(2026);
  for (int i = 0; i < 300; ++i) {
    const std::array<Vec2, 3> v{Vec2{rng.uniform(-20, 140), rng.uniform(-20, 140)},
                                Vec2{rng.uniform(-20, 140), rng.uniform(-20, 140)},
                                Vec2{rng.uniform(-20, 140), rng.uniform(-20, 140)}};
    // Values whose interpolation would not reproduce them bit for bit.
    const Color c{rng.uniform(0, 1), 0.1, 1.0 / 3.0};
    const std::array<Color, 3> colors{c, c, c};
    for (Method method : {Method::exact, Method::float32, Method::double64}) {
      ColorCanvas canvas(120, 120);
      FillScratch scratch;
      fill_polygon(canvas, PolygonInput{v, colors, 0, std::nullopt},
                   FillOptions{.shading = Shading::gouraud, .method = method}, scratch);
      const auto ref = sttest::ref_rasterize(120, 120, v, colors, FillRule::top_left);
      for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 120; ++x) {
          INFO("triangle " << i << ", " << to_string(method) << ", pixel " << x << "," << y);
          const bool written = canvas.written[y * 120 + x];
          if (method == Method::exact) REQUIRE(ref.at(x, y) == written);
          if (written) REQUIRE(canvas.pixels[y * 120 + x] == c);
        }
    }
  }
}
