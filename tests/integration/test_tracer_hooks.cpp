// The fill's tracer hooks report what the fill really did: spans equal the pixels written, pixel
// events equal the image, and tracing never changes the image.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "recording_tracer.hpp"
#include "src/painter.hpp"
#include "src/scanline_fill.hpp"

using namespace scantrace;
using scantrace::testing::RecordingTracer;

namespace {

constexpr Rgb32f kBackground{-1, -1, -1};  // no triangle colour can produce it
constexpr int kW = 96, kH = 80;

struct RandomTriangle {
  std::array<Vec2, 3> v;
  std::array<Color, 3> c;
};

RandomTriangle random_triangle(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> pos(-20.0, 110.0), col(0.0, 1.0);
  RandomTriangle t;
  for (auto& p : t.v) p = {std::round(pos(rng) * 4) / 4, std::round(pos(rng) * 4) / 4};
  for (auto& c : t.c) c = {col(rng), col(rng), col(rng)};
  return t;
}

bool written(const RgbImage& img, int x, int y) {
  return !(img(x, y) == kBackground);
}

}  // namespace

TEST_CASE("scanline spans and pixel events equal what the fill wrote", "[trace]") {
  std::mt19937_64 rng(7);
  for (Shading shading : {Shading::flat, Shading::gouraud}) {
    for (int i = 0; i < 300; ++i) {
      const RandomTriangle t = random_triangle(rng);
      RgbImage img(kW, kH, kBackground);
      RecordingTracer tracer;
      const FillResult r = fill_triangle(img, t.v, t.c, FillOptions{.shading = shading}, tracer);
      CAPTURE(i, t.v[0].x, t.v[0].y, t.v[1].x, t.v[1].y, t.v[2].x, t.v[2].y);

      if (r.skipped != SkipReason::none) {
        CHECK(tracer.skipped.at(0) == r.skipped);
        CHECK(tracer.scanlines.empty());
        continue;
      }
      REQUIRE(tracer.ended.size() == 1);
      CHECK(static_cast<i64>(tracer.scanlines.size()) == r.rows);
      std::vector<int> traced_row(kH, 0);
      for (const auto& s : tracer.scanlines) {
        CAPTURE(s.y);
        REQUIRE(s.y >= 0);
        REQUIRE(s.y < kH);
        traced_row[s.y] = 1;
        // Under the top-left rule a triangle has exactly two active edges on each of its rows.
        CHECK(s.active_edges.size() == 2);
        CHECK(s.active_points.size() == 2);
        CHECK(s.active_points[0].x <= s.active_points[1].x);
        for (int x = 0; x < kW; ++x) {
          const bool in_span = s.has_span && x >= s.x_begin && x < s.x_end;
          CHECK(written(img, x, static_cast<int>(s.y)) == in_span);
        }
        if (s.has_span && shading == Shading::gouraud) {
          REQUIRE(s.has_span_colors);
          const Color first = img(static_cast<int>(s.x_begin), static_cast<int>(s.y)).color();
          const Color last = img(static_cast<int>(s.x_end - 1), static_cast<int>(s.y)).color();
          // Every channel of both ends (a colour with two channels swapped must fail).
          CHECK(s.span_begin.r == Approx(first.r).margin(1e-6));
          CHECK(s.span_begin.g == Approx(first.g).margin(1e-6));
          CHECK(s.span_begin.b == Approx(first.b).margin(1e-6));
          CHECK(s.span_end.r == Approx(last.r).margin(1e-6));
          CHECK(s.span_end.g == Approx(last.g).margin(1e-6));
          CHECK(s.span_end.b == Approx(last.b).margin(1e-6));
        }
      }
      // Rows the trace does not mention hold no pixel of the triangle.
      for (int y = 0; y < kH; ++y)
        if (!traced_row[y])
          for (int x = 0; x < kW; ++x) CHECK_FALSE(written(img, x, y));
      // Pixel events: one per written pixel, with the colour that was stored.
      CHECK(static_cast<i64>(tracer.pixels.size()) == r.pixels);
      for (const auto& p : tracer.pixels) {
        const Rgb32f stored = img(static_cast<int>(p.x), static_cast<int>(p.y));
        CHECK(Rgb32f::from(p.color) == stored);
        CHECK(p.t >= 0.0);
        CHECK(p.t <= 1.0);
      }
    }
  }
}

TEST_CASE("entered and retired edges follow the edge table", "[trace]") {
  // (20,20), (250,80), (300,400): edge 0 = v0→v1, 1 = v1→v2, 2 = v2→v0. Rows 20…79 are crossed
  // by edges 0 and 2; at row 80 edge 0 (which ends at y = 80) retires and edge 1 enters.
  RgbImage img(512, 512, Rgb32f{1, 1, 1});
  RecordingTracer tracer;
  fill_triangle(img, {Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}},
                {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}}, FillOptions{}, tracer);
  REQUIRE(tracer.scanlines.size() == 380);  // rows 20 … 399
  const auto& first = tracer.scanlines.front();
  CHECK(first.y == 20);
  CHECK(first.entered == std::vector<int>{0, 2});
  const auto& row80 = tracer.scanlines[60];
  REQUIRE(row80.y == 80);
  CHECK(row80.retired == std::vector<int>{0});
  CHECK(row80.entered == std::vector<int>{1});
  for (const auto& s : tracer.scanlines)
    if (s.y != 20 && s.y != 80) CHECK((s.entered.empty() && s.retired.empty()));
}

TEST_CASE("tracing does not change the image", "[trace]") {
  Scene scene;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pos(-30.0, 140.0), unit(0.0, 1.0);
  for (int i = 0; i < 120; ++i) {
    scene.vertices.push_back({pos(rng), pos(rng)});
    scene.vcolors.push_back({unit(rng), unit(rng), unit(rng)});
    scene.depth.push_back(unit(rng));
  }
  for (int f = 0; f < 40; ++f) scene.faces.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  scene.width = 128;
  scene.height = 100;
  REQUIRE_FALSE(validate(scene).has_value());

  const RgbImage plain = render(scene);
  RecordingTracer tracer;
  tracer.only = {5, 17};
  const RgbImage traced = render(scene, FillOptions{}, tracer);
  CHECK(traced == plain);
  // The triangle filter holds: only the selected faces were narrated.
  for (const auto& s : tracer.scanlines) CHECK((s.triangle == 5 || s.triangle == 17));
  for (int t : tracer.begun) CHECK((t == 5 || t == 17));
}
