#pragma once
// Where a sweep writes one polygon's rows, one row after the other: the image's row and, near to
// far, the coverage mask's row (occlusion_canvas.hpp), each reached by stepping a pointer held in
// a register. After a store through a byte pointer, canvas.row(y) would reload the image's address
// and width, and fields of the canvas would be reloaded the same way, so a sweep keeps its cursor
// in a local variable. The sweeps of src/scanline_fill.hpp (edge steppers, small triangles) share it.
#include <cstddef>
#include <cstdint>

#include "src/canvas.hpp"
#include "src/color.hpp"
#include "coverage_mask.hpp"
#include "src/fixed_point.hpp"
#include "flat_span.hpp"
#include "occlusion_canvas.hpp"
#include "shaded_span.hpp"

namespace scantrace {

template <Canvas C>
struct RowCursor {
  [[maybe_unused]] DirectPixel<C>* row = nullptr;
  [[maybe_unused]] std::ptrdiff_t row_stride = 0;
  // Near to far: the mask's row, and whether this face's spans need clipping at all (its box may
  // be all uncovered); then the pixels the face claimed, which the canvas is told at the end.
  [[maybe_unused]] std::uint64_t* cover = nullptr;
  [[maybe_unused]] std::ptrdiff_t cover_stride = 0;
  [[maybe_unused]] bool clip = false;
  [[maybe_unused]] i64 claimed = 0;

  [[gnu::always_inline]] RowCursor(C& canvas, i64 y) {
    if constexpr (DirectCanvas<C>)
      row = canvas.row(static_cast<int>(y)), row_stride = canvas.row_stride();
    if constexpr (CoverageCanvas<C>)
      cover = canvas.coverage_row(static_cast<int>(y)), cover_stride = canvas.coverage_stride(),
      clip = canvas.clipping();
  }

  [[gnu::always_inline]] void next_row() {
    if constexpr (DirectCanvas<C>) row += row_stride;
    if constexpr (CoverageCanvas<C>) cover += cover_stride;
  }

  // Pixels [xb, xe) of the current row (row y) := the flat colour, in the canvas's pixel format
  // when it has one; near to far only where no nearer face drew. The pixel is the caller's, made
  // once per polygon, by reference: a copy per row would be stored just before the run writer
  // below reads it (see there).
  [[gnu::always_inline]] void fill_flat(C& canvas, FlatRow& flat_row, const DirectPixel<C>& pixel,
                                        Color flat, int y, int xb, int xe) {
    if constexpr (CoverageCanvas<C>) {
      if (clip) {
        // The run writer is inlined into claim()'s common case (a span in one word, all new):
        // called, it reads the pixel back from the stack in loads wider than the stores that
        // wrote it, which cannot be forwarded (docs/performance.md, "Why the fast code looks as it does").
        const auto run = [&](int a, int b) __attribute__((always_inline)) {
          fill(flat_row, pixel, a, b);
        };
        claimed += CoverageMask::claim(cover, xb, xe, run);
      } else {
        CoverageMask::mark(cover, xb, xe);
        claimed += xe - xb;
        fill(flat_row, pixel, xb, xe);
      }
    } else if constexpr (DirectCanvas<C>) {
      fill(flat_row, pixel, xb, xe);
    } else {
      canvas.fill_span(y, xb, xe, flat);
    }
  }

  // Pixels [xb, xe) of the current row := the exact method's Gouraud colours c, c + step, … in
  // the canvas's pixel format (shaded_span.hpp); near to far only where no nearer face drew.
  [[gnu::always_inline]] void shade(int xb, int xe, Color c, Color step) {
    if constexpr (CoverageCanvas<C>) {
      if (clip) {
        ShadedSpan<DirectPixel<C>> part(xb, xe, c, step);
        // Inlined as fill_flat's run writer is, for the same reason.
        const auto run = [&](int a, int b) __attribute__((always_inline)) {
          part.write(row, a, b);
        };
        claimed += CoverageMask::claim(cover, xb, xe, run);
      } else {
        CoverageMask::mark(cover, xb, xe);
        claimed += xe - xb;
        shade_pixels(row, xb, xe, c, step);
      }
    } else {
      shade_pixels(row, xb, xe, c, step);
    }
  }

  // Near to far: whether nearer faces already cover all of [xb, xe) of the current row, so that
  // a Gouraud span there costs neither its colours nor a store. Never so on other canvases.
  [[gnu::always_inline]] bool hidden(int xb, int xe) const {
    if constexpr (CoverageCanvas<C>) return clip && CoverageMask::covered(cover, xb, xe);
    return false;
  }

  // Pixels [xb, xe) of the row: most spans of a small triangle are a few pixels, stored here
  // without a call; FlatRow takes the longer ones (flat_span.hpp).
  [[gnu::always_inline]] void fill(FlatRow& flat_row, DirectPixel<C> pixel, int xb, int xe) {
    if (!fill_few(row + xb, row + xe, pixel)) flat_row.fill(row + xb, row + xe, pixel);
  }

  // The polygon is done: a canvas that counts what it wrote is told.
  void finish(C& canvas) const {
    if constexpr (CoverageCanvas<C>) canvas.add_written(claimed);
  }
};

}  // namespace scantrace
