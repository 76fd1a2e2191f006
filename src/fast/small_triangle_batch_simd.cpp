// The SIMD kernel of small_triangle_batch.hpp, compiled once per Highway target (foreach_target.h)
// and chosen at run time for the CPU (simd_targets.hpp).
//
// Each step is the scalar set-up's (src/fill_setup.hpp, src/fixed_point.hpp, small_triangle.hpp,
// src/flat_color.hpp) on a vector of faces, in doubles: snapping is floor(v) plus one where
// v − floor(v) ≥ 1/2, a pixel bound is a power-of-two division rounded up, and the products of
// the area, the bound and the edge functions stay below 2^53 on every lane that is kept. A lane
// is kept only when every check of the scalar path passes; any other lane's values are not read.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/fast/small_triangle_batch_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "src/fixed_point.hpp"
#include "src/fast/simd_targets.hpp"
#include "src/fast/small_triangle_batch.hpp"

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

using D = hn::ScalableTag<double>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

// The constants of a batch's target, as vectors.
struct Target {
  explicit Target(const BatchTarget& t)
      : scale(static_cast<double>(std::int64_t{1} << t.subpixel_bits)),
        s(hn::Set(D(), scale)),
        inv_s(hn::Set(D(), 1.0 / scale)),
        width(hn::Set(D(), t.width)),
        last_col(hn::Set(D(), t.width - 1.0)),
        band_begin(hn::Set(D(), t.band.begin)),
        band_last(hn::Set(D(), t.band.end - 1.0)),
        cull(t.cull) {}
  double scale;
  V s, inv_s, width, last_col, band_begin, band_last;
  Cull cull;
};

// SubpixelGrid::representable, then snap: floor(v + 1/2) of v = coordinate · 2^bits. The lanes
// whose coordinates are all in range.
HWY_INLINE M SnapVertices(const TriangleBatch& in, std::size_t j, const Target& t, V (&x)[3],
                          V (&y)[3]) {
  const D d;
  const auto one = hn::Set(d, 1.0), half = hn::Set(d, 0.5), range = hn::Set(d, kMaxCoordinate);
  auto ok = hn::Eq(hn::Zero(d), hn::Zero(d));
  for (int i = 0; i < 3; ++i) {
    const auto vx = hn::LoadU(d, in.x[i] + j), vy = hn::LoadU(d, in.y[i] + j);
    ok = hn::And(ok, hn::And(hn::Le(hn::Abs(vx), range), hn::Le(hn::Abs(vy), range)));
    const auto sx = hn::Mul(vx, t.s), sy = hn::Mul(vy, t.s);
    const auto fx = hn::Floor(sx), fy = hn::Floor(sy);
    x[i] = hn::Add(fx, hn::IfThenElseZero(hn::Ge(hn::Sub(sx, fx), half), one));
    y[i] = hn::Add(fy, hn::IfThenElseZero(hn::Ge(hn::Sub(sy, fy), half), one));
  }
  return ok;
}

// The pixels a lane's face may own, clipped to the canvas and the band.
struct Box {
  V col0, row0, cols, rows;
  M ok;  // the box is not empty, meets the canvas and the band, and fits small_triangle
};

// grid_box under the top-left rule, covers_pixels, and small_triangle's limits.
HWY_INLINE Box PixelBox(const V (&x)[3], const V (&y)[3], const Target& t) {
  const D d;
  const auto zero = hn::Zero(d), one = hn::Set(d, 1.0);
  const auto x_min = hn::Min(hn::Min(x[0], x[1]), x[2]), x_max = hn::Max(hn::Max(x[0], x[1]), x[2]);
  const auto y_min = hn::Min(hn::Min(y[0], y[1]), y[2]), y_max = hn::Max(hn::Max(y[0], y[1]), y[2]);
  const auto col_first = hn::Ceil(hn::Mul(x_min, t.inv_s));
  const auto col_last = hn::Sub(hn::Ceil(hn::Mul(x_max, t.inv_s)), one);
  const auto row_first = hn::Ceil(hn::Mul(y_min, t.inv_s));
  const auto row_last = hn::Sub(hn::Ceil(hn::Mul(y_max, t.inv_s)), one);
  auto ok = hn::And(hn::Le(col_first, col_last), hn::Le(row_first, row_last));
  ok = hn::And(ok, hn::And(hn::Ge(col_last, zero), hn::Lt(col_first, t.width)));
  ok = hn::And(ok, hn::And(hn::Ge(row_last, t.band_begin), hn::Le(row_first, t.band_last)));
  Box b;
  b.col0 = hn::Max(col_first, zero);
  b.row0 = hn::Max(row_first, t.band_begin);
  b.cols = hn::Add(hn::Sub(hn::Min(col_last, t.last_col), b.col0), one);
  b.rows = hn::Add(hn::Sub(hn::Min(row_last, t.band_last), b.row0), one);
  ok = hn::And(ok, hn::And(hn::Ge(b.cols, one), hn::Ge(b.rows, one)));
  ok = hn::And(ok, hn::And(hn::Le(b.cols, hn::Set(d, kSmallTriangleCols)),
                           hn::Le(b.rows, hn::Set(d, kSmallTriangleRows))));
  const auto dx = hn::Sub(x_max, x_min), dy = hn::Sub(y_max, y_min);
  const auto side = hn::Set(d, 16777216.0);  // 2^24
  ok = hn::And(ok, hn::And(hn::Le(dx, side), hn::Le(dy, side)));
  const auto bound =
      hn::Add(hn::Add(hn::Mul(dy, hn::Add(dx, hn::Set(d, 2.0 * kSmallTriangleLanes * t.scale))),
                      hn::Mul(dx, hn::Add(dy, hn::Set(d, 2.0 * t.scale)))),
              one);
  b.ok = hn::And(ok, hn::Le(bound, hn::Set(d, 2147483647.0)));
  return b;
}

// small_triangle's edge functions at the box's first pixel, the inside made positive, and their
// steps per column and per row.
HWY_INLINE void StoreEdgeFunctions(const V (&x)[3], const V (&y)[3], M positive, const Box& b,
                                   const Target& t, std::size_t j, BatchSetup& out) {
  const D d;
  const auto zero = hn::Zero(d), one = hn::Set(d, 1.0);
  const auto sign = hn::IfThenElse(positive, one, hn::Neg(one));
  const auto x0 = hn::Mul(b.col0, t.s), y0 = hn::Mul(b.row0, t.s);
  for (int i = 0; i < 3; ++i) {
    const int k = i == 2 ? 0 : i + 1;
    const auto ex = hn::Neg(hn::Mul(sign, hn::Sub(y[k], y[i])));
    const auto ey = hn::Mul(sign, hn::Sub(x[k], x[i]));
    const auto tie = hn::IfThenElseZero(
        hn::Or(hn::Gt(ex, zero), hn::And(hn::Eq(ex, zero), hn::Gt(ey, zero))), one);
    const auto at =
        hn::Add(hn::Add(hn::Mul(ex, hn::Sub(x0, x[i])), hn::Mul(ey, hn::Sub(y0, y[i]))), tie);
    hn::StoreU(at, d, out.at[i] + j);
    hn::StoreU(hn::Mul(ex, t.s), d, out.per_col[i] + j);
    hn::StoreU(hn::Mul(ey, t.s), d, out.per_row[i] + j);
  }
}

// flat_color of each lane's three vertex colours.
HWY_INLINE void StoreFlatColors(const TriangleBatch& in, std::size_t j, BatchSetup& out) {
  const D d;
  const auto third = hn::Set(d, 1.0 / 3.0);
  const auto mean = [&](const double(&c)[3][kTriangleBatch], double* to) {
    hn::StoreU(Mean3(hn::LoadU(d, c[0] + j), hn::LoadU(d, c[1] + j), hn::LoadU(d, c[2] + j), third),
               d, to + j);
  };
  mean(in.r, out.r);
  mean(in.g, out.g);
  mean(in.b, out.b);
}

void SmallTriangleBatch(const TriangleBatch& in, const BatchTarget& bt, BatchSetup& out) {
  const D d;
  const Target t(bt);
  const auto zero = hn::Zero(d), one = hn::Set(d, 1.0);
  for (std::size_t j = 0; j < kTriangleBatch; j += hn::Lanes(d)) {
    V x[3], y[3];
    const M in_range = SnapVertices(in, j, t, x, y);
    const Box box = PixelBox(x, y, t);
    // twice_area, non-zero, and culling on its sign (src/fill_options.hpp, Cull).
    const auto area2 = hn::Sub(hn::Mul(hn::Sub(x[1], x[0]), hn::Sub(y[2], y[0])),
                               hn::Mul(hn::Sub(x[2], x[0]), hn::Sub(y[1], y[0])));
    const auto positive = hn::Gt(area2, zero);
    auto ok = hn::And(hn::And(in_range, box.ok), hn::Ne(area2, zero));
    if (t.cull == Cull::back) ok = hn::AndNot(positive, ok);
    if (t.cull == Cull::front) ok = hn::AndNot(hn::Lt(area2, zero), ok);
    hn::StoreU(hn::IfThenElseZero(ok, one), d, out.small + j);
    StoreEdgeFunctions(x, y, positive, box, t, j, out);
    hn::StoreU(box.col0, d, out.col0 + j);
    hn::StoreU(box.cols, d, out.cols + j);
    hn::StoreU(box.row0, d, out.row0 + j);
    hn::StoreU(box.rows, d, out.rows + j);
    StoreFlatColors(in, j, out);
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
