#pragma once
// A small flat triangle's spans, a row of pixels at a time in SIMD lanes.
//
// A course triangle covers about 21 pixels over 16 rows: the scanline sweep's exact edge starts
// (a 128-bit product and two divisions per edge) and its per-row stepping cost far more than its
// pixels. Inside a small box the three edge functions of the half-space test are exact in 32 bits,
// so a row's pixel centres can be tested all at once, one lane each: a centre is inside when the
// three edge functions are positive there, or zero on an edge that owns its ties under the
// top-left rule. That is the sweep's rule (src/halfspace_fill.hpp derives it), so each row gets the
// same span, bit for bit: a convex triangle meets a row in one run, from its first inside lane to
// its last. Only coverage comes from here; a Gouraud colour is the sweep's function of its edges'
// crossings, so shaded triangles stay with the sweep.
//
// The kernel (small_triangle_simd.cpp) is compiled for each Highway target and chosen at run time
// (simd_targets.hpp): 16 lanes of AVX-512 test a row of a 16-pixel box in one step.
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>

#include "row_cursor.hpp"
#include "simd_targets.hpp"
#include "src/canvas.hpp"
#include "src/fill_result.hpp"
#include "src/fill_setup.hpp"
#include "src/fixed_point.hpp"

namespace scantrace {

// Pixels [begin, end) of one row; begin >= end when the row has none. No default values: a
// buffer of them is left uninitialised until the kernel writes it.
struct RowSpan {
  std::int32_t begin, end;
};

// A triangle's pixel box (clipped to the canvas and the band) and its edge functions in 32 bits.
struct SmallTriangle {
  // Edge i's function at the centre of pixel (col0, row0), plus one when the edge owns its ties:
  // a centre is inside when all three are positive. Then its change per column and per row.
  std::array<std::int32_t, 3> at{}, per_col{}, per_row{};
  int col0 = 0, cols = 0, row0 = 0, rows = 0;
  friend bool operator==(const SmallTriangle&, const SmallTriangle&) = default;
};

// The largest box the fast path takes. A wider triangle has longer spans, on which the sweep's
// per-row cost is spent on more pixels; a box of more rows would need a larger span buffer.
inline constexpr int kSmallTriangleCols = 32;
inline constexpr int kSmallTriangleRows = 128;
// The most lanes a kernel tests past a row's last column (AVX-512: 16 lanes of 32 bits).
inline constexpr int kSmallTriangleLanes = 16;

// Sets `t` up for the triangle `p` (snapped, its bounding box `box` under the top-left rule,
// `positive` the sign of twice its area, which is not zero: both known to the fill already): false
// when its box is larger than the limits above, or when an edge function could leave 32 bits on
// the lanes the kernel tests.
inline bool small_triangle(std::span<const FixedPoint> p, const GridBox& box, bool positive,
                           const SubpixelGrid& grid, int width, RowBand band, SmallTriangle& t) {
  const i64 col0 = std::max<i64>(box.col_first, 0), col1 = std::min<i64>(box.col_last, width - 1);
  const i64 row0 = std::max<i64>(box.row_first, band.begin);
  const i64 row1 = std::min<i64>(box.row_last, band.end - 1);
  if (col1 < col0 || row1 < row0 || col1 - col0 >= kSmallTriangleCols ||
      row1 - row0 >= kSmallTriangleRows)
    return false;
  // The lanes evaluated lie at x in [x_min, x_max + 2·lanes·s) (a row's last vector, and the step
  // past it) and y in [y_min, y_max + 2s] (the rows stepped past the last, two at a time): at most
  // |∂E/∂x|·(dx + 2·lanes·s) + |∂E/∂y|·(dy + 2s) from a vertex, where each coefficient is at most
  // the box's size. That, plus the tie's one, must fit in 32 bits.
  const i64 s = grid.scale(), dx = box.x_max - box.x_min, dy = box.y_max - box.y_min;
  constexpr i64 kLimit = INT32_MAX;
  if (dx > (i64{1} << 24) || dy > (i64{1} << 24) ||
      dy * (dx + 2 * kSmallTriangleLanes * s) + dx * (dy + 2 * s) + 1 > kLimit)
    return false;

  const i64 sign = positive ? 1 : -1;  // makes the inside positive
  for (int i = 0; i < 3; ++i) {
    const FixedPoint a = p[i], b = p[i == 2 ? 0 : i + 1];
    const i64 ex = -sign * (b.y - a.y), ey = sign * (b.x - a.x);  // per grid unit
    // A left edge (inside to its right) and a top edge (horizontal, inside below) own their ties.
    const i64 tie = ex > 0 || (ex == 0 && ey > 0) ? 1 : 0;
    t.at[i] = static_cast<std::int32_t>(ex * (col0 * s - a.x) + ey * (row0 * s - a.y) + tie);
    t.per_col[i] = static_cast<std::int32_t>(ex * s);
    t.per_row[i] = static_cast<std::int32_t>(ey * s);
  }
  t.col0 = static_cast<int>(col0), t.cols = static_cast<int>(col1 - col0 + 1);
  t.row0 = static_cast<int>(row0), t.rows = static_cast<int>(row1 - row0 + 1);
  return true;
}

// Rows [0, t.rows) of t's box as spans of absolute columns, by the best kernel the CPU runs.
void small_triangle_spans(const SmallTriangle& t, RowSpan* out);

using SmallTriangleFunction = void (*)(const SmallTriangle&, RowSpan*);
// The kernels this CPU can run, best first (the first is small_triangle_spans's); tests run each.
std::span<const SimdKernelOf<SmallTriangleFunction>> small_triangle_kernels();

// A small triangle of one colour: its rows' spans from the SIMD kernel,
// written as the convex rule writes a flat span, and the same counts.
template <Canvas C>
FillResult fill_small_triangle(C& canvas, const SmallTriangle& t, Color color, FlatRow& flat_row) {
  // The pixel first, the spans after: the rows read the pixel from memory (RowCursor::fill_flat
  // takes it by reference), and the kernel's call between its stores and their first load lets
  // them reach the cache. Made after the kernel, the pixel would be loaded right after its
  // stores in wider loads, which cannot be forwarded: a stall on every face (docs/performance.md, "Why the fast code looks as it does").
  DirectPixel<C> pixel{};
  if constexpr (DirectCanvas<C>) pixel = C::convert(color);
  std::array<RowSpan, kSmallTriangleRows> spans;  // only rows [0, t.rows) are written and read
  small_triangle_spans(t, spans.data());
  RowCursor<C> at(canvas, t.row0);
  i64 pixels = 0;
  for (int r = 0;;) {
    const RowSpan span = spans[r];
    if (span.begin < span.end) {
      at.fill_flat(canvas, flat_row, pixel, color, t.row0 + r, span.begin, span.end);
      pixels += span.end - span.begin;
    }
    if (++r == t.rows) break;
    at.next_row();
  }
  at.finish(canvas);
  return {SkipReason::none, t.rows, pixels};
}

}  // namespace scantrace
