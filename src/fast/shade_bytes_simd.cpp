// The SIMD kernel of shade_bytes.hpp, compiled once per Highway target (foreach_target.h) and
// chosen at run time for the CPU (simd_targets.hpp says how, and why not by libhwy).
//
// Each channel's 32.32 value is kept as two 32-bit lanes, high and low word, so a vector holds as
// many pixels as it has 32-bit lanes (64-bit lanes would halve that, and x86 has no 64-bit
// multiply before AVX-512). Stepping a lane by N pixels adds N·step word by word, the low word's
// carry taken from an unsigned compare: exactly the 64-bit sum, whose high word is the byte.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/fast/shade_bytes_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/fast/shade_bytes.hpp"
#include "src/fast/simd_targets.hpp"

HWY_BEFORE_NAMESPACE();
namespace scantrace {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void ShadeBytes(Bgr8* out, int n, const ByteRamp& r, const ByteRamp& g, const ByteRamp& b) {
  const hn::ScalableTag<std::uint32_t> d;
  const hn::Rebind<std::uint8_t, decltype(d)> d8;
  const int lanes = static_cast<int>(hn::Lanes(d));
  constexpr std::uint64_t kHalf = std::uint64_t{1} << 31;

  // Lane j of channel c starts at pixel j; the sums wrap modulo 2^64 like the scalar int64 ones,
  // whose values never leave [0, 255·2^32 + 2^31], so the high words agree.
  HWY_ALIGN std::uint32_t lo[3][HWY_MAX_BYTES / 4], hi[3][HWY_MAX_BYTES / 4];
  const ByteRamp* ramp[3] = {&b, &g, &r};  // Bgr8's order
  for (int c = 0; c < 3; ++c)
    for (int j = 0; j < lanes; ++j) {
      const std::uint64_t v =
          static_cast<std::uint64_t>(ramp[c]->start) +
          static_cast<std::uint64_t>(j) * static_cast<std::uint64_t>(ramp[c]->step) + kHalf;
      lo[c][j] = static_cast<std::uint32_t>(v);
      hi[c][j] = static_cast<std::uint32_t>(v >> 32);
    }
  auto step_of = [&](int c) {
    return static_cast<std::uint64_t>(lanes) * static_cast<std::uint64_t>(ramp[c]->step);
  };
  const std::uint64_t s0 = step_of(0), s1 = step_of(1), s2 = step_of(2);
  const auto slo0 = hn::Set(d, static_cast<std::uint32_t>(s0));
  const auto shi0 = hn::Set(d, static_cast<std::uint32_t>(s0 >> 32));
  const auto slo1 = hn::Set(d, static_cast<std::uint32_t>(s1));
  const auto shi1 = hn::Set(d, static_cast<std::uint32_t>(s1 >> 32));
  const auto slo2 = hn::Set(d, static_cast<std::uint32_t>(s2));
  const auto shi2 = hn::Set(d, static_cast<std::uint32_t>(s2 >> 32));
  auto lo0 = hn::Load(d, lo[0]), hi0 = hn::Load(d, hi[0]);
  auto lo1 = hn::Load(d, lo[1]), hi1 = hn::Load(d, hi[1]);
  auto lo2 = hn::Load(d, lo[2]), hi2 = hn::Load(d, hi[2]);
  // hi += step_hi + carry: the carry's mask is all ones, i.e. −1, so it is subtracted.
  const auto advance = [&](auto& l, auto& h, auto sl, auto sh) {
    l = hn::Add(l, sl);
    h = hn::Sub(hn::Add(h, sh), hn::VecFromMask(d, hn::Lt(l, sl)));
  };

  auto* bytes = reinterpret_cast<std::uint8_t*>(out);
  int k = 0;
  for (; k + lanes <= n; k += lanes) {
    hn::StoreInterleaved3(hn::U8FromU32(hi0), hn::U8FromU32(hi1), hn::U8FromU32(hi2), d8,
                          bytes + 3 * k);
    advance(lo0, hi0, slo0, shi0);
    advance(lo1, hi1, slo1, shi1);
    advance(lo2, hi2, slo2, shi2);
  }
  for (; k < n; ++k) out[k] = {b.at(k), g.at(k), r.at(k)};
}

}  // namespace HWY_NAMESPACE
}  // namespace scantrace
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace scantrace {

std::span<const SimdKernel> shade_bytes_kernels() {
  static const std::vector<SimdKernel> kernels =
      runnable_kernels<ShadeBytesFunction>(SCANTRACE_KERNEL_TARGETS(ShadeBytes));
  return kernels;
}

void shade_bytes_simd(Bgr8* out, int n, const ByteRamp& r, const ByteRamp& g, const ByteRamp& b) {
  static const ShadeBytesFunction best = shade_bytes_kernels().front().function;
  best(out, n, r, g, b);
}

}  // namespace scantrace
#endif  // HWY_ONCE
