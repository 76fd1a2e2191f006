// The 8-bit canvas: every covered pixel holds round(255·c) of the exact reference colour c
// (barycentric at the pixel centre), up to one level where 255·c lies within the fill's colour
// error of a rounding boundary; coverage equals the reference's.
#include <catch2/catch.hpp>

#include <cmath>

#include "reference_raster.hpp"
#include "src/scanline_fill.hpp"
#include "src/splitmix64.hpp"

using namespace scantrace;

TEST_CASE("8-bit canvas: Gouraud and flat pixels are the rounded exact colours", "[bgr8]") {
  SplitMix64 rng(88);
  const int size = 300;
  long long checked = 0;
  for (int i = 0; i < 200; ++i) {
    const double extent = i % 4 == 0 ? 4000 : 300;  // some spans far longer than the canvas
    const std::array<Vec2, 3> v{Vec2{rng.uniform(-50, extent), rng.uniform(-50, 350)},
                                Vec2{rng.uniform(-extent, 350), rng.uniform(-50, 350)},
                                Vec2{rng.uniform(-50, 350), rng.uniform(-50, 350)}};
    const std::array<Color, 3> c{Color{rng.uniform(0, 1), rng.uniform(0, 1), 0},
                                 Color{rng.uniform(0, 1), 1, rng.uniform(0, 1)},
                                 Color{0, rng.uniform(0, 1), rng.uniform(0, 1)}};
    const auto ref = sttest::ref_rasterize(size, size, v, c, FillRule::top_left);
    for (Shading shading : {Shading::flat, Shading::gouraud}) {
      Bgr8Image image(size, size, Bgr8{1, 2, 3});
      fill_triangle(image, v, c, FillOptions{.shading = shading});
      const Color flat = sttest::mean_color(c);
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
          const Bgr8 got = image(x, y);
          INFO("triangle " << i << ", " << to_string(shading) << ", pixel " << x << "," << y);
          REQUIRE(ref.at(x, y) == !(got == Bgr8{1, 2, 3}));
          if (!ref.at(x, y)) continue;
          const Color want = shading == Shading::flat ? flat : ref.color_at(x, y);
          const double chans[3][2] = {
              {want.r, double(got.r)}, {want.g, double(got.g)}, {want.b, double(got.b)}};
          for (const auto& [w, g] : chans) {
            const double level = 255 * w;
            const double off_boundary = std::fabs(level - std::floor(level) - 0.5);
            if (off_boundary > 1e-6)
              REQUIRE(g == std::floor(level + 0.5));
            else
              REQUIRE(std::fabs(g - level) <= 0.5 + 1e-6);
            ++checked;
          }
        }
    }
  }
  CHECK(checked > 1000000);
}
