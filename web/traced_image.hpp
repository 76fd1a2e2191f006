#pragma once
// The image a kept trace's fill drew (st_trace with options.keep, web/bindings_trace.cpp), and its
// RGBA bytes, kept in the module from one call to the next. The explorer traces the dragged
// triangle on every mouse move: a new 512 x 512 canvas allocated, cleared and freed, and its 1 MB
// of RGBA bytes zeroed and cleared again, were a third of the call (docs/performance.md, "Ninth
// round"). Kept, only the pixels the last fill wrote are put back to the background before the
// next fill, when the last trace says which they are.
#include <cstdint>
#include <vector>

#include "src/image.hpp"
#include "trace/trace.hpp"

namespace scantrace::web {

class TracedImage {
 public:
  // The canvas made width x height of `background` for the next fill: by putting back the pixels
  // of the spans of `last` (the trace of the last fill, which set_from_spans described) when the
  // size and background are the same, else cleared whole. The bytes alike.
  RgbImage& canvas_for(int width, int height, const Color& background, const trace::Trace* last);

  // After the fill: the bytes from the canvas's pixels in `t`'s spans (all it wrote: a whole trace
  // of an edge-table fill), the rest being the background canvas_for left; the next canvas_for
  // may then put back only those spans.
  void set_from_spans(const trace::Trace& t);
  // After a fill whose pixels the trace does not all say (halfspace, a filtered or cut trace):
  // every pixel converted; the next canvas_for clears everything.
  void set_from_every_pixel();
  // The kept trace was replaced by one this image was not drawn for (a scene's): the next
  // canvas_for clears everything.
  void forget() { spans_only_ = false; }

  const std::vector<std::uint8_t>& rgba() const { return rgba_; }

 private:
  RgbImage canvas_;
  std::vector<std::uint8_t> rgba_;  // canvas_ as put_rgba converts it
  Rgb32f background_{};
  bool spans_only_ = false;  // canvas_ and rgba_ are background_ but in the last trace's spans
};

}  // namespace scantrace::web
