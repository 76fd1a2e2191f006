// OcclusionCanvas::finish, the near-to-far render's background: it writes the background on
// exactly the pixels of its band that the coverage mask leaves uncovered, whatever the lengths and
// order of those runs, and nothing else. Checked against the mask read pixel by pixel, on pixels
// that each held a value of their own before. (The float64 image's background is most of its
// bytes: ways of writing it faster are tried against this test; docs/performance.md.)
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "random.hpp"
#include "src/fast/flat_span.hpp"
#include "src/fast/occlusion_canvas.hpp"

namespace {

using namespace scantrace;

// A 24-byte pixel, as the float64 image's (python/src/array_canvas.hpp): a run of 342 pixels is
// 8 KiB, the length from which glibc's memcpy changes strategy (rep movsb).
struct Wide {
  double r = 0, g = 0, b = 0;
  static Wide from(Color c) { return {c.r, c.g, c.b}; }
  friend bool operator==(Wide, Wide) = default;
};

template <class P>
P own_value(int x, int y) {
  return P::from(Color{static_cast<double>(x), static_cast<double>(y), -1.0});
}

template <class P>
void check_finish(std::uint64_t seed) {
  constexpr int kWidth = 700, kHeight = 64;
  const RowBand band{5, 59};
  sttest::Rng rng(seed);
  CoverageMask mask;
  mask.reset(kWidth, kHeight);
  // Per row, 0-5 covered segments of random places and lengths: uncovered runs from one pixel to
  // the whole row (rows 20 and 40 are all uncovered, row 30 all covered), long and short in
  // random order.
  for (int y = 0; y < kHeight; ++y) {
    if (y == 20 || y == 40) continue;
    if (y == 30) {
      mask.mark(y, 0, kWidth);
      continue;
    }
    const int segments = static_cast<int>(rng.uniform(0, 6));
    for (int s = 0; s < segments; ++s) {
      const int a = static_cast<int>(rng.uniform(0, kWidth));
      const int n = static_cast<int>(rng.uniform(1, rng.uniform(0, 1) < 0.5 ? 8 : 300));
      mask.mark(y, a, std::min(kWidth, a + n));
    }
  }
  std::vector<std::vector<bool>> covered(kHeight, std::vector<bool>(kWidth));
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) covered[y][x] = mask.covered(y, x, x + 1);

  // The test is only as good as its runs: long ones no longer than one before them (a writer
  // may copy those from an earlier run) and long ones longer than every one before.
  int longest = 0, copied = 0, written_long = 0;
  for (int y = band.begin; y < band.end; ++y)
    for (int x = 0; x < kWidth;) {
      if (covered[y][x]) {
        ++x;
        continue;
      }
      int n = 0;
      while (x + n < kWidth && !covered[y][x + n]) ++n;
      if (n > kShortSpan) (n <= longest ? copied : written_long) += 1;
      longest = std::max(longest, n);
      x += n;
    }
  REQUIRE(copied >= 20);
  REQUIRE(written_long >= 2);

  Image<P> image(kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) image(x, y) = own_value<P>(x, y);
  const P background = P::from(Color{0.25, 0.5, 0.75});
  OcclusionCanvas<P> canvas(image, mask, band);
  canvas.finish(background);

  long long wrong = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const bool inside = y >= band.begin && y < band.end;
      const P expected = inside && !covered[y][x] ? background : own_value<P>(x, y);
      if (!(image(x, y) == expected)) ++wrong;
    }
  CHECK(wrong == 0);
  for (int y = band.begin; y < band.end; ++y) CHECK(mask.covered(y, 0, kWidth));
}

}  // namespace

TEST_CASE("occlusion canvas: finish writes the background on the uncovered pixels of its band only",
          "[occlusion]") {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    INFO("seed " << seed);
    check_finish<Wide>(seed);
    check_finish<Rgb32f>(seed);
  }
}
