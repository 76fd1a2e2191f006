// A Gouraud triangle whose three vertex colours are equal is filled as a flat one: every covered
// pixel holds exactly that colour (not a colour interpolated to within rounding of it), and the
// coverage is the exact reference's.
#include <catch2/catch.hpp>

#include "reference_raster.hpp"
#include "src/scanline_fill.hpp"
#include "src/splitmix64.hpp"

using namespace scantrace;

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
      RgbImage image(120, 120, Rgb32f{-1, -1, -1});
      fill_triangle(image, v, colors, FillOptions{.shading = Shading::gouraud, .method = method});
      const auto ref = sttest::ref_rasterize(120, 120, v, colors, FillRule::top_left);
      for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 120; ++x) {
          INFO("triangle " << i << ", " << to_string(method) << ", pixel " << x << "," << y);
          if (method == Method::exact) REQUIRE(ref.at(x, y) == (image(x, y).r >= 0));
          if (image(x, y).r >= 0) REQUIRE(image(x, y) == Rgb32f::from(c));
        }
    }
  }
}
