#pragma once
// A Gouraud span of 8-bit pixels in fixed point: each channel as 255·c in 32.32 bits, stepped by
// an integer increment and rounded by a shift. Converting doubles to bytes costs two conversions
// per channel and pixel; this costs an add and a shift. The ends are clamped to [0, 255] first,
// and every pixel lies between them (the increment is truncated toward zero), so no pixel can wrap
// around; the truncations stay below 2^-32 of a level per pixel, i.e. below 1e-8 in colour over
// the longest span.
//
// Long spans go to a SIMD kernel (shade_bytes_simd.cpp, Google Highway, the target chosen at run
// time: one binary uses SSE4, AVX2 or AVX-512 where the CPU has them). It computes the same
// integers as the scalar loop below, so the pixels are bit-identical on every target; short spans,
// which are most spans of a course scene, stay inline, where a call would cost more than it saves.
#include <cstdint>
#include <span>

#include "src/color.hpp"
#include "src/image.hpp"
#include "simd_targets.hpp"

namespace scantrace {

// One channel of a span: pixel k gets (start + k·step + 2^31) >> 32.
struct ByteRamp {
  std::int64_t start = 0, step = 0;

  // The ramp from `first` (pixel 0) to `last` (pixel n − 1), both clamped to [0, 1].
  static ByteRamp between(double first, double last, int n) {
    const std::int64_t a = fixed(first), b = fixed(last);
    return {a, n > 1 ? (b - a) / (n - 1) : 0};
  }
  // The same ramp begun k pixels later: pixel j of it is pixel k + j of this one, bit for bit
  // (a span drawn in parts, src/canvas.hpp's ShadedSpan).
  ByteRamp skip(int k) const { return {start + k * step, step}; }
  std::uint8_t at(int k) const {
    return static_cast<std::uint8_t>((start + k * step + (std::int64_t{1} << 31)) >> 32);
  }

 private:
  static std::int64_t fixed(double v) {
    constexpr double kTop = 255.0 * 4294967296.0;  // 255 · 2^32
    const double x = kTop * v;
    return static_cast<std::int64_t>(x > 0.0 ? (x < kTop ? x : kTop) : 0.0);
  }
};

// Pixels [0, n) of `out` from their three ramps, by the SIMD kernel of the best target the CPU
// supports (any n ≥ 0).
void shade_bytes_simd(Bgr8* out, int n, const ByteRamp& r, const ByteRamp& g, const ByteRamp& b);

// One compiled kernel: its Highway target and entry point.
using ShadeBytesFunction = void (*)(Bgr8*, int, const ByteRamp&, const ByteRamp&, const ByteRamp&);
using SimdKernel = SimdKernelOf<ShadeBytesFunction>;
// The kernels this CPU can run, best first (the first is shade_bytes_simd's); tests run each.
std::span<const SimdKernel> shade_bytes_kernels();

// From this length on a span goes to the SIMD kernel (measured: bench/, docs/performance.md).
inline constexpr int kSimdSpan = 48;

// The three ramps of a span of n pixels coloured c, c + step, …
struct ByteRamps {
  ByteRamp r, g, b;
  ByteRamps(int n, Color c, Color step) {
    const Color last = c + step * static_cast<double>(n - 1);
    r = ByteRamp::between(c.r, last.r, n);
    g = ByteRamp::between(c.g, last.g, n);
    b = ByteRamp::between(c.b, last.b, n);
  }
  ByteRamps(const ByteRamp& r, const ByteRamp& g, const ByteRamp& b) : r(r), g(g), b(b) {}
  ByteRamps skip(int k) const { return {r.skip(k), g.skip(k), b.skip(k)}; }
};

// Pixels [0, n) of `out` from their ramps.
inline void shade_ramps(Bgr8* out, int n, const ByteRamps& ramps) {
  const auto& [r, g, b] = ramps;
  if (n >= kSimdSpan) [[unlikely]]
    return shade_bytes_simd(out, n, r, g, b);
  for (int k = 0; k < n; ++k) out[k] = {b.at(k), g.at(k), r.at(k)};
}

inline void shade_bytes(Bgr8* out, int n, Color c, Color step) {
  if (n <= 0) return;
  shade_ramps(out, n, ByteRamps(n, c, step));
}

}  // namespace scantrace
