// The SIMD kernel of small_triangle_batch.hpp, compiled once per Highway target (foreach_target.h)
// and chosen at run time for the CPU (simd_targets.hpp).
//
// Each step is the scalar set-up's (fill_setup.hpp, fixed_point.hpp, small_triangle.hpp,
// flat_color.hpp) on a vector of faces, in doubles: snapping is floor(v) plus one where
// v − floor(v) ≥ 1/2, a pixel bound is a power-of-two division rounded up, and the products of
// the area, the bound and the edge functions stay below 2^53 on every lane that is kept. A lane
// is kept only when every check of the scalar path passes; any other lane's values are not read.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/small_triangle_batch_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/fixed_point.hpp"
#include "src/simd_targets.hpp"
#include "src/small_triangle_batch.hpp"

HWY_BEFORE_NAMESPACE();
namespace scantrace {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// std::min and std::max as flat_color calls them, NaN included: min(a, b) is b < a ? b : a.
template <class V>
HWY_INLINE V MinAsStd(V a, V b) {
  return hn::IfThenElse(hn::Lt(b, a), b, a);
}
template <class V>
HWY_INLINE V MaxAsStd(V a, V b) {
  return hn::IfThenElse(hn::Lt(a, b), b, a);
}

// flat_color's sum of three values, smallest first, times 1/3.
template <class V>
HWY_INLINE V Mean3(V a, V b, V c, V third) {
  const V lo = MinAsStd(a, b), hi = MaxAsStd(a, b);
  const V sum = hn::Add(hn::Add(MinAsStd(lo, c), MaxAsStd(lo, MinAsStd(hi, c))), MaxAsStd(hi, c));
  return hn::Mul(sum, third);
}

void SmallTriangleBatch(const TriangleBatch& in, const BatchTarget& t, BatchSetup& out) {
  const hn::ScalableTag<double> d;
  const std::size_t lanes = hn::Lanes(d);
  const double scale = static_cast<double>(std::int64_t{1} << t.subpixel_bits);
  const auto s = hn::Set(d, scale), inv_s = hn::Set(d, 1.0 / scale);
  const auto zero = hn::Zero(d), one = hn::Set(d, 1.0), half = hn::Set(d, 0.5);
  const auto range = hn::Set(d, kMaxCoordinate);
  const auto width = hn::Set(d, t.width), last_col = hn::Set(d, t.width - 1.0);
  const auto band_begin = hn::Set(d, t.band.begin), band_last = hn::Set(d, t.band.end - 1.0);
  const auto third = hn::Set(d, 1.0 / 3.0);
  for (std::size_t j = 0; j < kTriangleBatch; j += lanes) {
    // SubpixelGrid::representable, then snap: floor(v + 1/2) of v = coordinate · 2^bits.
    auto ok = hn::Eq(zero, zero);
    hn::Vec<decltype(d)> x[3], y[3];
    for (int i = 0; i < 3; ++i) {
      const auto vx = hn::LoadU(d, in.x[i] + j), vy = hn::LoadU(d, in.y[i] + j);
      ok = hn::And(ok, hn::And(hn::Le(hn::Abs(vx), range), hn::Le(hn::Abs(vy), range)));
      const auto sx = hn::Mul(vx, s), sy = hn::Mul(vy, s);
      const auto fx = hn::Floor(sx), fy = hn::Floor(sy);
      x[i] = hn::Add(fx, hn::IfThenElseZero(hn::Ge(hn::Sub(sx, fx), half), one));
      y[i] = hn::Add(fy, hn::IfThenElseZero(hn::Ge(hn::Sub(sy, fy), half), one));
    }
    // grid_box under the top-left rule, covers_pixels, and small_triangle's limits.
    const auto x_min = hn::Min(hn::Min(x[0], x[1]), x[2]),
               x_max = hn::Max(hn::Max(x[0], x[1]), x[2]);
    const auto y_min = hn::Min(hn::Min(y[0], y[1]), y[2]),
               y_max = hn::Max(hn::Max(y[0], y[1]), y[2]);
    const auto col_first = hn::Ceil(hn::Mul(x_min, inv_s));
    const auto col_last = hn::Sub(hn::Ceil(hn::Mul(x_max, inv_s)), one);
    const auto row_first = hn::Ceil(hn::Mul(y_min, inv_s));
    const auto row_last = hn::Sub(hn::Ceil(hn::Mul(y_max, inv_s)), one);
    ok = hn::And(ok, hn::And(hn::Le(col_first, col_last), hn::Le(row_first, row_last)));
    ok = hn::And(ok, hn::And(hn::Ge(col_last, zero), hn::Lt(col_first, width)));
    ok = hn::And(ok, hn::And(hn::Ge(row_last, band_begin), hn::Le(row_first, band_last)));
    const auto col0 = hn::Max(col_first, zero), col1 = hn::Min(col_last, last_col);
    const auto row0 = hn::Max(row_first, band_begin), row1 = hn::Min(row_last, band_last);
    const auto cols = hn::Add(hn::Sub(col1, col0), one), rows = hn::Add(hn::Sub(row1, row0), one);
    ok = hn::And(ok, hn::And(hn::Ge(cols, one), hn::Ge(rows, one)));
    ok = hn::And(ok, hn::And(hn::Le(cols, hn::Set(d, kSmallTriangleCols)),
                             hn::Le(rows, hn::Set(d, kSmallTriangleRows))));
    const auto dx = hn::Sub(x_max, x_min), dy = hn::Sub(y_max, y_min);
    const auto side = hn::Set(d, 16777216.0);  // 2^24
    ok = hn::And(ok, hn::And(hn::Le(dx, side), hn::Le(dy, side)));
    const auto bound =
        hn::Add(hn::Add(hn::Mul(dy, hn::Add(dx, hn::Set(d, 2.0 * kSmallTriangleLanes * scale))),
                        hn::Mul(dx, hn::Add(dy, hn::Set(d, 2.0 * scale)))),
                one);
    ok = hn::And(ok, hn::Le(bound, hn::Set(d, 2147483647.0)));
    // twice_area, non-zero, and culling on its sign (fill_options.hpp, Cull).
    const auto area2 = hn::Sub(hn::Mul(hn::Sub(x[1], x[0]), hn::Sub(y[2], y[0])),
                               hn::Mul(hn::Sub(x[2], x[0]), hn::Sub(y[1], y[0])));
    const auto positive = hn::Gt(area2, zero);
    ok = hn::And(ok, hn::Ne(area2, zero));
    if (t.cull == Cull::back) ok = hn::AndNot(positive, ok);
    if (t.cull == Cull::front) ok = hn::AndNot(hn::Lt(area2, zero), ok);
    hn::StoreU(hn::IfThenElseZero(ok, one), d, out.small + j);
    // small_triangle's edge functions, the inside made positive.
    const auto sign = hn::IfThenElse(positive, one, hn::Neg(one));
    const auto x0 = hn::Mul(col0, s), y0 = hn::Mul(row0, s);
    for (int i = 0; i < 3; ++i) {
      const int k = i == 2 ? 0 : i + 1;
      const auto ex = hn::Neg(hn::Mul(sign, hn::Sub(y[k], y[i])));
      const auto ey = hn::Mul(sign, hn::Sub(x[k], x[i]));
      const auto tie = hn::IfThenElseZero(
          hn::Or(hn::Gt(ex, zero), hn::And(hn::Eq(ex, zero), hn::Gt(ey, zero))), one);
      const auto at =
          hn::Add(hn::Add(hn::Mul(ex, hn::Sub(x0, x[i])), hn::Mul(ey, hn::Sub(y0, y[i]))), tie);
      hn::StoreU(at, d, out.at[i] + j);
      hn::StoreU(hn::Mul(ex, s), d, out.per_col[i] + j);
      hn::StoreU(hn::Mul(ey, s), d, out.per_row[i] + j);
    }
    hn::StoreU(col0, d, out.col0 + j);
    hn::StoreU(cols, d, out.cols + j);
    hn::StoreU(row0, d, out.row0 + j);
    hn::StoreU(rows, d, out.rows + j);
    // flat_color.
    const auto mean = [&](const double(&c)[3][kTriangleBatch], double* to) {
      hn::StoreU(
          Mean3(hn::LoadU(d, c[0] + j), hn::LoadU(d, c[1] + j), hn::LoadU(d, c[2] + j), third), d,
          to + j);
    };
    mean(in.r, out.r);
    mean(in.g, out.g);
    mean(in.b, out.b);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace scantrace
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace scantrace {

std::span<const SimdKernelOf<SmallTriangleBatchFunction>> small_triangle_batch_kernels() {
  static const std::vector<SimdKernelOf<SmallTriangleBatchFunction>> kernels =
      runnable_kernels<SmallTriangleBatchFunction>(SCANTRACE_KERNEL_TARGETS(SmallTriangleBatch));
  return kernels;
}

void small_triangle_batch(const TriangleBatch& in, const BatchTarget& target, BatchSetup& out) {
  static const SmallTriangleBatchFunction best = small_triangle_batch_kernels().front().function;
  best(in, target, out);
}

}  // namespace scantrace
#endif  // HWY_ONCE
