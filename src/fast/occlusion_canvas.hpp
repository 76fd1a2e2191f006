#pragma once
// The canvas of the near-to-far render (src/painter.hpp): faces come nearest first, and each pixel
// keeps the first colour written to it. That is the painter's image, without its overdraw: the
// painter's order reversed (ties included, so equal depths keep the same winner) makes the face
// that the painter would paint last the first one here.
//
// Spans are clipped against a CoverageMask before any pixel is computed: the fill asks whether a
// span is all covered before it sets up the span's colours, and writes only the runs the mask
// gives back. A face whose bounding box is all covered is rejected before its set-up, and one
// whose box nothing covers is drawn without clipping (begin_face()).
// The background is written last, only where no face drew (finish()).
#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>

#include "src/canvas.hpp"
#include "coverage_mask.hpp"

namespace scantrace {

// A canvas that writes a pixel only the first time: the fill clips its spans against it
// (src/scanline_fill.hpp) and the render loop asks it to reject hidden faces (src/painter.hpp).
template <class C>
concept CoverageCanvas = DirectCanvas<C> &&
    requires(C& c, int y, long long n, std::span<const Vec2> v) {
  { c.begin_face(v) } -> std::same_as<bool>;
  { c.clipping() } -> std::same_as<bool>;
  { c.coverage_row(y) } -> std::same_as<std::uint64_t*>;  // CoverageMask::row
  { c.coverage_stride() } -> std::same_as<std::ptrdiff_t>;
  c.add_written(n);
};

// Rows `band` of an image and of one coverage mask of the image's size (all the rows, or a band
// of the parallel render: bands own disjoint rows, so they share the mask without contention).
template <class P>
class OcclusionCanvas : public BandCanvas<P> {
 public:
  using BandCanvas<P>::row, BandCanvas<P>::convert, BandCanvas<P>::rows, BandCanvas<P>::width;

  OcclusionCanvas(Image<P>& image, CoverageMask& mask, RowBand band)
      : BandCanvas<P>(image, band), mask_(mask) {}

  // The sweep (src/scanline_fill.hpp) clips its spans against the mask's rows itself, with the
  // CoverageMask's static functions, and reports the pixels it wrote.
  std::uint64_t* coverage_row(int y) { return mask_.row(y); }
  std::ptrdiff_t coverage_stride() const { return mask_.stride(); }
  void add_written(long long pixels) { written_ += pixels; }

  // Pixels [x_begin, x_end) of row y that nothing covers yet, as visit(a, b) per run.
  template <class Visit>
  void claim(int y, int x_begin, int x_end, Visit&& visit) {
    written_ += mask_.claim(y, x_begin, x_end, visit);
  }

  // The fills that write through the canvas (other methods than the exact one, the half-space
  // fill) are clipped here, pixel run by pixel run.
  void fill_span(int y, int x_begin, int x_end, Color c) {
    const P p = convert(c);
    if (!clipping_) {
      mark(y, x_begin, x_end);
      return fill_pixels(row(y) + x_begin, row(y) + x_end, p);
    }
    claim(y, x_begin, x_end, [&](int a, int b) { fill_pixels(row(y) + a, row(y) + b, p); });
  }
  void set(int x, int y, Color c) {
    if (!clipping_) {
      mark(y, x, x + 1);
      row(y)[x] = convert(c);
      return;
    }
    claim(y, x, x + 1, [&](int, int) { row(y)[x] = convert(c); });
  }

  // Decides how the next face is drawn from its vertices (before snapping): false when every
  // pixel it could own in this band (face_pixels, src/canvas.hpp) is covered already, and it is not
  // drawn at all; otherwise, whether its spans must be clipped (clipping()): a face whose box
  // nothing covers yet writes its spans whole and only marks them, which is all a scene that hides
  // nothing pays for the bookkeeping (a convex face owns each pixel once, so its own spans never
  // overlap). A box that misses the band is drawn, with clipping: the fill's own set-up then says
  // why the face draws nothing.
  bool begin_face(std::span<const Vec2> vertices) {
    clipping_ = true;
    const PixelBox box = face_pixels(vertices, width(), rows());
    if (box.empty()) return true;
    const CoverageMask::Cover c = mask_.cover(box.y0, box.y1 + 1, box.x0, box.x1 + 1);
    clipping_ = c != CoverageMask::Cover::none;
    return c != CoverageMask::Cover::all;
  }
  bool clipping() const { return clipping_; }
  // Pixels [x_begin, x_end) of row y, written whole by a face that needs no clipping.
  void mark(int y, int x_begin, int x_end) {
    mask_.mark(y, x_begin, x_end);
    written_ += x_end - x_begin;
  }

  // The background on every pixel of the band that no face drew.
  void finish(P background) {
    const RowBand band = rows();
    for (int y = band.begin; y < band.end; ++y)
      mask_.claim(y, 0, width(),
                  [&](int a, int b) { fill_pixels(row(y) + a, row(y) + b, background); });
  }

  // Pixels written by faces so far (each once).
  long long written() const { return written_; }

 private:
  CoverageMask& mask_;
  long long written_ = 0;
  bool clipping_ = true;  // the current face's (begin_face)
};

}  // namespace scantrace
