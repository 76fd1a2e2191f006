// The SIMD kernel of small_triangle.hpp, compiled once per Highway target (foreach_target.h) and
// chosen at run time for the CPU (simd_targets.hpp).
//
// A vector holds one edge function at as many consecutive pixel centres of a row as it has 32-bit
// lanes. A fourth function, the columns left in the box, is positive on the lanes inside it, so
// the minimum of the four is positive exactly on the centres to fill. The three edge functions
// step by one constant per row and per vector of columns: integer adds, exact. A box at most half
// a vector wide takes two rows a vector.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/fast/small_triangle_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/fast/simd_targets.hpp"
#include "src/fast/small_triangle.hpp"

HWY_BEFORE_NAMESPACE();
namespace scantrace {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The span of the consecutive set bits of `inside` (bit j: column col0 + j), or none.
HWY_INLINE RowSpan SpanOf(std::uint64_t inside, int col0) {
  if (inside == 0) return RowSpan{0, 0};
  const int first = col0 + std::countr_zero(inside);
  return RowSpan{first, first + std::popcount(inside)};
}

// A box at most half a vector wide: two rows a vector, lanes [0, half) the row r and
// [half, lanes) the row r + 1, so a small triangle's rows cost half the steps. Its lanes beyond the
// box's columns are masked by the columns left, as in the general loop.
template <class D>
HWY_INLINE void TwoRowsAVector(D d, const SmallTriangle& t, RowSpan* out) {
  const int lanes = static_cast<int>(hn::Lanes(d)), half = lanes / 2;
  HWY_ALIGN std::int32_t init[4][HWY_MAX_BYTES / 4];
  for (int j = 0; j < lanes; ++j) {
    const int col = j % half, row = j / half;
    for (int i = 0; i < 3; ++i) init[i][j] = t.at[i] + t.per_col[i] * col + t.per_row[i] * row;
    init[3][j] = t.cols - col;
  }
  auto a = hn::Load(d, init[0]), b = hn::Load(d, init[1]), c = hn::Load(d, init[2]);
  const auto left = hn::Load(d, init[3]);
  const auto down0 = hn::Set(d, 2 * t.per_row[0]), down1 = hn::Set(d, 2 * t.per_row[1]),
             down2 = hn::Set(d, 2 * t.per_row[2]);
  const auto zero = hn::Zero(d);
  const std::uint64_t row_bits = (std::uint64_t{1} << half) - 1;
  for (int r = 0; r < t.rows; r += 2) {
    const auto inside = hn::Gt(hn::Min(hn::Min(a, b), hn::Min(c, left)), zero);
    std::uint8_t bytes[8] = {};
    hn::StoreMaskBits(d, inside, bytes);
    std::uint64_t bits = 0;
    std::memcpy(&bits, bytes, sizeof bits);
    out[r] = SpanOf(bits & row_bits, t.col0);
    if (r + 1 < t.rows) out[r + 1] = SpanOf((bits >> half) & row_bits, t.col0);
    a = hn::Add(a, down0), b = hn::Add(b, down1), c = hn::Add(c, down2);
  }
}

void SmallTriangleSpans(const SmallTriangle& t, RowSpan* out) {
  const hn::ScalableTag<std::int32_t> d;
  const int lanes = static_cast<int>(hn::Lanes(d));
  if (lanes >= 2 && t.cols <= lanes / 2) return TwoRowsAVector(d, t, out);
  const auto iota = hn::Iota(d, 0);
  // Lane j of a row's first vector: the functions at column col0 + j.
  const auto e0 = hn::Add(hn::Set(d, t.at[0]), hn::Mul(iota, hn::Set(d, t.per_col[0])));
  const auto e1 = hn::Add(hn::Set(d, t.at[1]), hn::Mul(iota, hn::Set(d, t.per_col[1])));
  const auto e2 = hn::Add(hn::Set(d, t.at[2]), hn::Mul(iota, hn::Set(d, t.per_col[2])));
  const auto left = hn::Sub(hn::Set(d, t.cols), iota);  // columns left in the box
  const auto next0 = hn::Set(d, t.per_col[0] * lanes), next1 = hn::Set(d, t.per_col[1] * lanes),
             next2 = hn::Set(d, t.per_col[2] * lanes), next_left = hn::Set(d, lanes);
  const auto down0 = hn::Set(d, t.per_row[0]), down1 = hn::Set(d, t.per_row[1]),
             down2 = hn::Set(d, t.per_row[2]);
  const auto zero = hn::Zero(d);
  auto row0 = e0, row1 = e1, row2 = e2;
  for (int r = 0; r < t.rows; ++r) {
    auto a = row0, b = row1, c = row2, l = left;
    int begin = -1, end = 0;
    for (int col = 0;;) {
      const auto inside = hn::Gt(hn::Min(hn::Min(a, b), hn::Min(c, l)), zero);
      if (!hn::AllFalse(d, inside)) {
        // A convex triangle meets the row in one run, so the lanes inside are consecutive.
        const int first = col + static_cast<int>(hn::FindFirstTrue(d, inside));
        if (begin < 0) begin = first;
        end = first + static_cast<int>(hn::CountTrue(d, inside));
      } else if (begin >= 0) {
        break;  // the run has ended
      }
      col += lanes;
      if (col >= t.cols) break;
      a = hn::Add(a, next0), b = hn::Add(b, next1), c = hn::Add(c, next2),
      l = hn::Sub(l, next_left);
    }
    out[r] = begin >= 0 ? RowSpan{t.col0 + begin, t.col0 + end} : RowSpan{0, 0};
    row0 = hn::Add(row0, down0), row1 = hn::Add(row1, down1), row2 = hn::Add(row2, down2);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace scantrace
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace scantrace {

std::span<const SimdKernelOf<SmallTriangleFunction>> small_triangle_kernels() {
  static const std::vector<SimdKernelOf<SmallTriangleFunction>> kernels =
      runnable_kernels<SmallTriangleFunction>(SCANTRACE_KERNEL_TARGETS(SmallTriangleSpans));
  return kernels;
}

void small_triangle_spans(const SmallTriangle& t, RowSpan* out) {
  static const SmallTriangleFunction best = small_triangle_kernels().front().function;
  best(t, out);
}

}  // namespace scantrace
#endif  // HWY_ONCE
