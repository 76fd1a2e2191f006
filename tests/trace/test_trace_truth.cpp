// The trace is the truth: what it says was written is what is in the image.
#include <catch2/catch.hpp>
#include <random>

#include "src/painter.hpp"
#include "trace/record.hpp"

using namespace scantrace;
using namespace scantrace::trace;

namespace {

constexpr Color kSentinel{0.123, 0.456, 0.789};  // background no random triangle reproduces exactly

TriangleInput random_triangle(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> pos(-40.0, 170.0), col(0.0, 1.0);
  TriangleInput t;
  for (auto& v : t.vertices) v = {std::round(pos(rng) * 8) / 8, std::round(pos(rng) * 8) / 8};
  for (auto& c : t.colors) c = {col(rng), col(rng), col(rng)};
  t.width = 128;
  t.height = 96;
  t.background = kSentinel;
  return t;
}

bool is_background(const RgbImage& img, i64 x, i64 y) {
  return img(static_cast<int>(x), static_cast<int>(y)) == Rgb32f::from(kSentinel);
}

}  // namespace

TEST_CASE("every traced row's span is exactly the pixels written on that row", "[trace]") {
  std::mt19937_64 rng(2024);
  for (Shading shading : {Shading::flat, Shading::gouraud})
    for (int i = 0; i < 200; ++i) {
      const TriangleInput t = random_triangle(rng);
      RgbImage image;
      const Trace trace = record_triangle(t, FillOptions{.shading = shading},
                                          TraceFilter{.level = TraceLevel::pixel}, &image);
      CAPTURE(i, to_string(shading));
      if (trace.skipped(0)) continue;
      std::vector<bool> row_traced(t.height, false);
      for (const Scanline* s : trace.scanlines(0)) {
        row_traced[s->y] = true;
        for (i64 x = 0; x < t.width; ++x)
          CHECK((s->span && s->span->contains(x)) == !is_background(image, x, s->y));
      }
      for (int y = 0; y < t.height; ++y)
        if (!row_traced[y])
          for (int x = 0; x < t.width; ++x) CHECK(is_background(image, x, y));

      // Pixel events equal the image, one per written pixel.
      i64 written = 0;
      for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x) written += !is_background(image, x, y);
      const auto pixels = trace.pixels(0);
      CHECK(static_cast<i64>(pixels.size()) == written);
      CHECK(trace.triangle_end(0)->pixels == written);
      for (const Pixel* p : pixels)
        CHECK(Rgb32f::from(p->color) == image(static_cast<int>(p->x), static_cast<int>(p->y)));
    }
}

TEST_CASE("pixel history of a scene ends with the colour in the image", "[trace]") {
  Scene scene;
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> pos(-20.0, 100.0), unit(0.0, 1.0);
  for (int i = 0; i < 90; ++i) {
    scene.vertices.push_back({pos(rng), pos(rng)});
    scene.vcolors.push_back({unit(rng), unit(rng), unit(rng)});
    scene.depth.push_back(unit(rng));
  }
  for (int f = 0; f < 30; ++f) scene.faces.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  scene.width = 80;
  scene.height = 80;
  scene.background = kSentinel;
  const std::vector<int> order = painter_order(face_depths(scene));

  for (TraceLevel level : {TraceLevel::scanline, TraceLevel::pixel})
    for (Shading shading : {Shading::flat, Shading::gouraud}) {
      RgbImage image;
      const Trace trace =
          record_scene(scene, FillOptions{.shading = shading}, TraceFilter{.level = level}, &image);
      CHECK(trace.triangles() == order);  // narrated in painter's order
      for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
          CAPTURE(x, y, static_cast<int>(level), to_string(shading));
          const PixelHistory h = trace.pixel_history(x, y);
          REQUIRE(h.empty() == is_background(image, x, y));
          if (h.empty()) continue;
          const Color c = h.final().color, stored = image(x, y).color();
          CHECK(h.final().from_pixel_event == (level == TraceLevel::pixel));
          CHECK(c.r == Approx(stored.r).margin(1e-6));
          CHECK(c.g == Approx(stored.g).margin(1e-6));
          CHECK(c.b == Approx(stored.b).margin(1e-6));
          // Writers appear in drawing order.
          for (std::size_t k = 1; k < h.writes.size(); ++k) {
            const auto pos_of = [&](int t) { return std::find(order.begin(), order.end(), t); };
            CHECK(pos_of(h.writes[k - 1].triangle) < pos_of(h.writes[k].triangle));
          }
        }
    }
}
