// The coverage mask of the near-to-far render gives back exactly the pixels of a span that no
// earlier span covered, as maximal runs, against a plain array of booleans kept in the test.
#include <catch2/catch.hpp>

#include <utility>
#include <vector>

#include "src/fast/coverage_mask.hpp"
#include "src/splitmix64.hpp"

using scantrace::CoverageMask;

TEST_CASE("coverage mask: runs are the uncovered pixels of each span, maximal and in order",
          "[occlusion]") {
  scantrace::SplitMix64 rng(19);
  // Widths around word boundaries, and spans from one pixel to whole rows.
  for (int width : {1, 63, 64, 65, 130, 300}) {
    const int height = 5;
    CoverageMask mask;
    mask.reset(width, height);
    std::vector<char> naive(static_cast<std::size_t>(width) * height, 0);
    for (int step = 0; step < 400; ++step) {
      const int y = static_cast<int>(rng.uniform(0, height - 1e-9));
      int a = static_cast<int>(rng.uniform(0, width)),
          b = static_cast<int>(rng.uniform(0, width + 1));
      if (a > b) std::swap(a, b);
      if (step % 7 == 0) a = 0, b = width;
      INFO("width " << width << ", row " << y << ", span [" << a << ", " << b << ")");
      // What the runs must be: the maximal runs of uncovered pixels in [a, b), left to right.
      std::vector<std::pair<int, int>> want;
      for (int x = a; x < b; ++x) {
        if (naive[y * width + x]) continue;
        if (!want.empty() && want.back().second == x)
          ++want.back().second;
        else
          want.push_back({x, x + 1});
      }
      const bool all_covered = want.empty();
      CHECK(mask.covered(y, a, b) == all_covered);
      std::vector<std::pair<int, int>> got;
      int claimed = mask.claim(y, a, b, [&](int p, int q) { got.push_back({p, q}); });
      CHECK(got == want);
      int want_count = 0;
      for (auto [p, q] : want) want_count += q - p;
      CHECK(claimed == want_count);
      for (int x = a; x < b; ++x) naive[y * width + x] = 1;
      CHECK(mask.covered(y, a, b));
      // A box over several rows is covered only when every pixel of it is.
      const int y0 = static_cast<int>(rng.uniform(0, height - 1e-9));
      bool box = true;
      for (int yy = y0; yy < height; ++yy)
        for (int x = a; x < b; ++x) box = box && naive[yy * width + x];
      CHECK(mask.covered(y0, height, a, b) == box);
    }
  }
}
