// FlatRow, the row of one colour that long flat spans are copied from: against a plain store loop
// over random spans whose value, pixel type and length change between calls (short, just over the
// short-span limit, longer than any before), with guard pixels on both sides left untouched.
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <vector>

#include "src/fast/flat_span.hpp"
#include "src/splitmix64.hpp"

using namespace scantrace;

namespace {

struct Rgb3 {  // 3 bytes, like Bgr8
  std::uint8_t c[3];
  bool operator==(const Rgb3&) const = default;
};
struct Rgbf {  // 12 bytes, like a float image
  float c[3];
  bool operator==(const Rgbf&) const = default;
};

template <class P, class Make>
void check_against_loop(FlatRow& row, SplitMix64& rng, Make make, int calls) {
  const int width = 5000, guard = 8;
  const P background = make(0.5);
  std::vector<P> got(width + 2 * guard, background), want = got;
  P value = make(rng.uniform(0, 1));
  for (int i = 0; i < calls; ++i) {
    if (rng.uniform(0, 1) < 0.3) value = make(rng.uniform(0, 1));  // a new polygon's colour
    const double kind = rng.uniform(0, 1);
    const int n = kind < 0.3   ? static_cast<int>(rng.uniform(0, 33))
                  : kind < 0.6 ? static_cast<int>(rng.uniform(33, 40))
                               : static_cast<int>(rng.uniform(33, width + 1));
    const int x = static_cast<int>(rng.uniform(0, width - n + 1));
    row.fill(got.data() + guard + x, got.data() + guard + x + n, value);
    for (int k = 0; k < n; ++k) want[guard + x + k] = value;
    INFO("call " << i << ": " << n << " pixels at " << x);
    REQUIRE(got == want);
  }
}

}  // namespace

TEST_CASE("FlatRow writes exactly the span, whatever came before", "[flat_row]") {
  SplitMix64 rng(2026);
  FlatRow row;  // one for all: its pattern outlives values, lengths and pixel types
  const auto rgb3 = [](double v) {
    const auto b = static_cast<std::uint8_t>(v * 255);
    return Rgb3{{b, static_cast<std::uint8_t>(255 - b), static_cast<std::uint8_t>(b / 2)}};
  };
  const auto rgbf = [](double v) {
    return Rgbf{{static_cast<float>(v), static_cast<float>(1 - v), static_cast<float>(v / 3)}};
  };
  for (int round = 0; round < 3; ++round) {
    check_against_loop<Rgb3>(row, rng, rgb3, 300);
    check_against_loop<Rgbf>(row, rng, rgbf, 300);
    check_against_loop<std::uint8_t>(
        row, rng, [](double v) { return std::uint8_t(v * 255); }, 300);
  }
}

TEST_CASE("FlatRow: a value equal to the pattern's first pixel only in part is a new value",
          "[flat_row]") {
  // A deliberately weak check (comparing fewer bytes than a pixel) would reuse the old row here.
  FlatRow row;
  std::vector<Rgbf> a(100);
  row.fill(a.data(), a.data() + 100, Rgbf{{1, 2, 3}});
  row.fill(a.data(), a.data() + 100, Rgbf{{1, 2, 4}});
  for (const Rgbf& p : a) REQUIRE(p == Rgbf{{1, 2, 4}});
}
