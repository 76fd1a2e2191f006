#pragma once
// The pixels written so far, as the trace tells them: what the replay shows as "filled". Colours
// come from the trace only — the pixel events when the trace has them (level pixel), otherwise
// each scanline's span with the flat colour or its span_colors (Gouraud is linear along a row) —
// converted to 8-bit BGR with the project's rounding rule. A triangle-level trace records each
// triangle's input but none of its pixels: those are filled again from the recorded vertices and
// colours by the same fill (src/), so that the replay still ends on the rendered image.
//
// Visibility follows the trace's header. Painter's order: every pixel written replaces what was
// there. Z-buffer: every pixel is depth-tested exactly as the render did it — the pixel events'
// recorded outcome, or else the depth recomputed from the triangle's snapped vertices and vertex
// depths (src/depth_plane.hpp) and compared with the depth stored so far (nearer wins, ties keep
// the first) — so that rejected pixels are never shown as written.
#include <cstdint>
#include <optional>
#include <vector>

#include "viz/geometry.hpp"

#include "trace/trace.hpp"

namespace scantrace::viz {

class CanvasState {
 public:
  // Keeps the canvas pixels inside `window` (canvas coordinates, already clipped to the canvas).
  // `depth_test`: the trace is of a z-buffer render (Header::visibility "zbuffer").
  explicit CanvasState(Rect window, bool depth_test = false);
  // The window, and the visibility of `trace`'s header.
  CanvasState(Rect window, const trace::Trace& trace);
  // A copy (the pixels are values: any copy is deep; kept for the callers that say so).
  CanvasState clone() const;

  // Writes the rows first_row..last_row of `triangle` (those the trace holds).
  void paint_rows(const trace::Trace& trace, int triangle, std::int64_t first_row,
                  std::int64_t last_row);
  // Every row of `triangle`; for a triangle-level trace, the triangle filled again (see above).
  void paint_triangle(const trace::Trace& trace, int triangle);

  const Rect& window() const { return window_; }
  bool depth_test() const { return depth_test_; }
  bool written(std::int64_t x, std::int64_t y) const;
  Vec3b bgr(std::int64_t x, std::int64_t y) const;  // only meaningful where written()
  // Canvas row y of the window, from its column window().x: the pixels and the mask (255:
  // written), for views that read whole rows; nullptr when the row is outside the window.
  const Vec3b* row_pixels(std::int64_t y) const;
  const std::uint8_t* row_mask(std::int64_t y) const;

  std::int64_t writes() const { return writes_; }          // pixel writes so far
  std::int64_t overwrites() const { return overwrites_; }  // of them, onto a written pixel
  std::int64_t rejected() const { return rejected_; }      // z-buffer: pixels the test rejected

  // Z-buffer: the pixels (inside the window) the depth test rejected since forget_recent(), which
  // the scene view marks on the frame of the step that drew them.
  const std::vector<Point>& recent_rejections() const { return recent_rejections_; }
  void forget_recent() { recent_rejections_.clear(); }

  // Writes pixel (x, y) in colour `c`; with a depth (z-buffer) only if it passes the test.
  void put(std::int64_t x, std::int64_t y, const Color& c, std::optional<double> depth = {});

 private:
  void store(std::int64_t x, std::int64_t y, const Color& c);
  void reject(std::int64_t x, std::int64_t y);
  void paint_scanline(const trace::Trace& trace, const trace::Scanline& s);
  void refill(const trace::Trace& trace, int triangle);
  bool inside(std::int64_t x, std::int64_t y) const;

  Rect window_;
  bool depth_test_ = false;
  std::size_t index(std::int64_t x, std::int64_t y) const;  // (x, y) inside the window

  int stride_ = 1;                  // pixels per row of the window's storage
  std::vector<Vec3b> image_;        // BGR, window-sized
  std::vector<std::uint8_t> mask_;  // 255 where written
  std::vector<double> depth_;       // +inf: nothing drawn yet (z-buffer only; else empty)
  std::int64_t writes_ = 0, overwrites_ = 0, rejected_ = 0;
  std::vector<Point> recent_rejections_;
};

// The colour the trace gives pixel x of scanline `s` (x inside its span): the flat colour, or
// the linear interpolation of span_colors between x_begin and x_end - 1.
Color span_pixel_colour(const trace::Scanline& s, const std::optional<Color>& flat, std::int64_t x);

}  // namespace scantrace::viz
