// The Gouraud span of 8-bit pixels: its SIMD kernel (src/fast/shade_bytes_simd.cpp) gives exactly the
// bytes of the fixed-point formula, computed here in 128-bit integers, with every Highway target's
// kernel this CPU can run; and shade_bytes, whichever path a length takes, stays
// within a rounding of the exact colours c + k·step.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "src/fast/shade_bytes.hpp"

using namespace scantrace;

namespace {

// Pixel k of a ramp, without the kernel's 32-bit words or the scalar loop's int64 wrap-around.
std::uint8_t expected(const ByteRamp& r, int k) {
  const __int128 v = static_cast<__int128>(r.start) + static_cast<__int128>(k) * r.step +
                     (static_cast<__int128>(1) << 31);
  return static_cast<std::uint8_t>(static_cast<long long>(v >> 32));
}

}  // namespace

TEST_CASE("the SIMD span equals the fixed-point formula on every target", "[core][simd]") {
  const std::span<const SimdKernel> kernels = shade_bytes_kernels();
  REQUIRE(!kernels.empty());
  // x86-64 always has SSSE3 or better: a list of only the portable kernel would mean the
  // selection went wrong.
#if defined(__x86_64__)
  CHECK(kernels.size() >= 2);
#endif
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> unit(-0.2, 1.2);  // ends beyond [0, 1] are clamped
  for (const SimdKernel& kernel : kernels) {
    INFO("Highway target " << kernel.target);
    int checked = 0;
    for (int trial = 0; trial < 400; ++trial) {
      // Every length up to 80 (vector tails of every size), then long spans.
      const int n = trial < 80 ? trial : static_cast<int>(rng() % 5000);
      const ByteRamp r = ByteRamp::between(unit(rng), unit(rng), n);
      const ByteRamp g = ByteRamp::between(unit(rng), unit(rng), n);
      const ByteRamp b = trial % 7 == 0 ? ByteRamp::between(0.5, 0.5, n)  // a flat channel
                                        : ByteRamp::between(unit(rng), unit(rng), n);
      // One guard pixel each side: the kernel writes [0, n) and nothing else.
      std::vector<Bgr8> out(static_cast<std::size_t>(n) + 2, Bgr8{1, 2, 3});
      kernel.function(out.data() + 1, n, r, g, b);
      REQUIRE(out.front() == Bgr8{1, 2, 3});
      REQUIRE(out.back() == Bgr8{1, 2, 3});
      for (int k = 0; k < n; ++k) {
        const Bgr8 want{expected(b, k), expected(g, k), expected(r, k)};
        if (!(out[k + 1] == want)) {
          INFO("n = " << n << ", pixel " << k);
          REQUIRE(out[k + 1] == want);
        }
        ++checked;
      }
    }
    CHECK(checked > 100000);
  }
}

TEST_CASE("a span of 8-bit pixels is its exact colours rounded", "[core][simd]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 1 + static_cast<int>(rng() % (trial < 150 ? 64 : 3000));  // both paths
    const Color c{unit(rng), unit(rng), unit(rng)};
    const Color last{unit(rng), unit(rng), unit(rng)};
    const Color step = n > 1 ? (last - c) * (1.0 / (n - 1)) : Color{};
    std::vector<Bgr8> out(n);
    shade_bytes(out.data(), n, c, step);
    for (int k = 0; k < n; ++k) {
      const Color exact = c + step * static_cast<double>(k);
      INFO("n = " << n << ", pixel " << k);
      // Within half a level and the fixed point's truncations (< 1e-6 of a level here).
      CHECK(std::abs(out[k].r - 255.0 * exact.r) <= 0.5 + 1e-6);
      CHECK(std::abs(out[k].g - 255.0 * exact.g) <= 0.5 + 1e-6);
      CHECK(std::abs(out[k].b - 255.0 * exact.b) <= 0.5 + 1e-6);
    }
  }
}

TEST_CASE("a short span writes its pixels, each its formula's bytes, and nothing else",
          "[core][simd]") {
  // Every length from 0 to 8 (the spans of a small triangle), between guard pixels, against the
  // formula per channel: each pixel its bytes, and nothing written outside the span.
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Bgr8 guard{7, 8, 9};
  for (int trial = 0; trial < 2000; ++trial) {
    const int n = static_cast<int>(trial % 9);
    const Color c{unit(rng), unit(rng), unit(rng)};
    const Color last{unit(rng), unit(rng), unit(rng)};
    const Color step = n > 1 ? (last - c) * (1.0 / (n - 1)) : Color{};
    const ByteRamps ramps(std::max(n, 1), c, step);
    std::vector<Bgr8> out(n + 8, guard);
    shade_ramps(out.data() + 4, n, ramps);
    for (int i = 0; i < n + 8; ++i) {
      INFO("n = " << n << ", pixel " << i - 4);
      if (i < 4 || i >= n + 4) {
        CHECK(out[i] == guard);
        continue;
      }
      const int k = i - 4;
      CHECK(out[i].r == expected(ramps.r, k));
      CHECK(out[i].g == expected(ramps.g, k));
      CHECK(out[i].b == expected(ramps.b, k));
    }
  }
}
