#pragma once
// Where the canvas appears on a frame: a region of canvas pixels magnified into a rectangle of
// the frame, every pixel a square cell. Pixel (x, y) is centred on the canvas point (x, y)
// (docs/design.md §2), so its cell spans x - 0.5 … x + 0.5.
#include <cstdint>
#include <optional>
#include <utility>

#include "viz/frame.hpp"

namespace scantrace::viz {

// Canvas pixels x0..x1, y0..y1 (inclusive).
struct PixelBox {
  std::int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  bool empty() const { return x1 < x0 || y1 < y0; }
  std::int64_t width() const { return x1 - x0 + 1; }
  std::int64_t height() const { return y1 - y0 + 1; }
};

// One canvas pixel, by column and row.
struct CanvasPixel {
  std::int64_t x = 0, y = 0;
  bool operator==(const CanvasPixel&) const = default;
};

class ViewGeometry {
 public:
  // Fits `region` into `view` (centred, cells square). Cells never exceed `max_cell` frame
  // pixels; from 4 px up they are a whole number of frame pixels, so grid lines stay crisp. The
  // view is then filled: pixels around the region are shown too.
  ViewGeometry(Rect view, PixelBox region, double max_cell);

  const Rect& view() const { return view_; }
  double cell() const { return cell_; }
  // Frame position of the canvas point (x, y).
  Point2d to_frame(double x, double y) const;
  // The canvas pixel shown at frame pixel (u, v) (which must lie in the view).
  std::int64_t pixel_x(int u) const;
  std::int64_t pixel_y(int v) const;
  PixelBox visible() const;  // every pixel with at least part of its cell in the view

 private:
  Rect view_;
  double cell_ = 1;
  double left_ = 0, top_ = 0;  // canvas coordinates at the view's left and top edges
};

// The part of segment p-q inside `r` (Liang-Barsky), in double so that a vertex at 1e9 pixels
// does not overflow the backends' integer coordinates; nullopt when nothing is inside.
std::optional<std::pair<Point2d, Point2d>> clip_segment(Point2d p, Point2d q, const Rect2d& r);

// A line with subpixel precision (1/16 pixel, cv::line's shift 4), clipped to `clip` first.
void draw_segment(FrameView& image, Point2d p, Point2d q, const Rect& clip, const Scalar& colour,
                  int thickness, std::optional<Mark> mark = std::nullopt);
// The same line drawn over a thicker `halo`, which keeps it visible on any background.
void draw_segment_with_halo(FrameView& image, Point2d p, Point2d q, const Rect& clip,
                            const Scalar& colour, int thickness, const Scalar& halo, int halo_width,
                            std::optional<Mark> mark = std::nullopt);

}  // namespace scantrace::viz
