#pragma once
// The pixels written so far, as the trace tells them: what the replay shows as "filled". Colours
// come from the trace only — the pixel events when the trace has them (level pixel), otherwise
// each scanline's span with the flat colour or its span_colors (Gouraud is linear along a row) —
// converted to 8-bit BGR with the project's rounding rule.
#include <cstdint>

#include <opencv2/core.hpp>

#include "trace/trace.hpp"

namespace scantrace::viz {

class CanvasState {
 public:
  // Keeps the canvas pixels inside `window` (canvas coordinates, already clipped to the canvas).
  explicit CanvasState(cv::Rect window);
  // A deep copy (copying a CanvasState shares its pixels, as cv::Mat does).
  CanvasState clone() const;

  // Writes the rows first_row..last_row of `triangle` (those the trace holds).
  void paint_rows(const trace::Trace& trace, int triangle, std::int64_t first_row,
                  std::int64_t last_row);
  void paint_triangle(const trace::Trace& trace, int triangle);

  const cv::Rect& window() const { return window_; }
  bool written(std::int64_t x, std::int64_t y) const;
  cv::Vec3b bgr(std::int64_t x, std::int64_t y) const;  // only meaningful where written()
  const cv::Mat& image() const { return image_; }       // CV_8UC3, window-sized
  const cv::Mat& mask() const { return mask_; }         // CV_8UC1, 255 where written

  std::int64_t writes() const { return writes_; }          // pixel writes so far
  std::int64_t overwrites() const { return overwrites_; }  // of them, onto a written pixel

 private:
  void put(std::int64_t x, std::int64_t y, const Color& c);
  void paint_scanline(const trace::Trace& trace, const trace::Scanline& s);

  cv::Rect window_;
  cv::Mat image_, mask_;
  std::int64_t writes_ = 0, overwrites_ = 0;
};

// The colour the trace gives pixel x of scanline `s` (x inside its span): the flat colour, or
// the linear interpolation of span_colors between x_begin and x_end - 1.
Color span_pixel_colour(const trace::Scanline& s, const std::optional<Color>& flat, std::int64_t x);

}  // namespace scantrace::viz
