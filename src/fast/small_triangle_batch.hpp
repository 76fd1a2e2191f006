#pragma once
// The set-up of small flat triangles, several faces at once in SIMD lanes.
//
// A small flat triangle's spans and stores (small_triangle.hpp) cost less than what comes before
// them: snapping its three corners, its exact area, its box, the checks that it reaches the canvas
// and fits the small path, its edge functions and its flat colour, face after face in scalar code
// (docs/performance.md: 10,000 triangles of 10 px² take 0.44 of their render in spans and
// stores). Here those steps run for a batch of faces in double lanes: a face the small path takes
// has a box of at most 33 columns and 129 rows (at most 2^24 grid units a side), where every value
// of the set-up is an integer below 2^53, so the double arithmetic is exact and gives the scalar
// set-up's values, bit for bit. Whatever the batch does not take (out of range, zero area, culled,
// off the canvas, too large) goes to fill_polygon, which decides it as before.
#include <array>
#include <cstdint>
#include <span>

#include "src/color.hpp"
#include "src/fill_options.hpp"
#include "simd_targets.hpp"
#include "small_triangle.hpp"
#include "src/vec2.hpp"

namespace scantrace {

inline constexpr int kTriangleBatch = 8;

// A batch of faces' corners and colours, one array per coordinate and channel, lane k face k.
// Lanes past `count` are ignored.
struct TriangleBatch {
  alignas(64) double x[3][kTriangleBatch], y[3][kTriangleBatch];
  alignas(64) double r[3][kTriangleBatch], g[3][kTriangleBatch], b[3][kTriangleBatch];

  // Face k's corners as given (the near-to-far box test and the z-buffer's depth plane take them).
  std::array<Vec2, 3> corners(int k) const {
    return {Vec2{x[0][k], y[0][k]}, Vec2{x[1][k], y[1][k]}, Vec2{x[2][k], y[2][k]}};
  }
};

// What the set-up needs of the fill: the grid, the canvas's columns and the band's rows, culling.
struct BatchTarget {
  int subpixel_bits = 0;
  int width = 0;
  RowBand band;
  Cull cull = Cull::none;
};

// Per face of the batch: whether the small path takes it (fill_polygon would: flat, exact,
// top-left, untraced), and then its set-up and its flat colour, as doubles holding the values.
struct BatchSetup {
  alignas(64) double small[kTriangleBatch];  // 1 or 0
  alignas(64) double at[3][kTriangleBatch], per_col[3][kTriangleBatch], per_row[3][kTriangleBatch];
  alignas(64) double col0[kTriangleBatch], cols[kTriangleBatch], row0[kTriangleBatch],
      rows[kTriangleBatch];
  alignas(64) double r[kTriangleBatch], g[kTriangleBatch], b[kTriangleBatch];

  SmallTriangle triangle(int k) const {
    SmallTriangle t;
    for (int i = 0; i < 3; ++i) {
      t.at[i] = static_cast<std::int32_t>(at[i][k]);
      t.per_col[i] = static_cast<std::int32_t>(per_col[i][k]);
      t.per_row[i] = static_cast<std::int32_t>(per_row[i][k]);
    }
    t.col0 = static_cast<int>(col0[k]), t.cols = static_cast<int>(cols[k]);
    t.row0 = static_cast<int>(row0[k]), t.rows = static_cast<int>(rows[k]);
    return t;
  }
  Color flat(int k) const { return {r[k], g[k], b[k]}; }
};

// The set-up of every face of `in`, by the best kernel the CPU runs.
void small_triangle_batch(const TriangleBatch& in, const BatchTarget& target, BatchSetup& out);

using SmallTriangleBatchFunction = void (*)(const TriangleBatch&, const BatchTarget&, BatchSetup&);
// The kernels this CPU can run, best first; tests run each.
std::span<const SimdKernelOf<SmallTriangleBatchFunction>> small_triangle_batch_kernels();

}  // namespace scantrace
