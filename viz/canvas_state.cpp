#include "viz/canvas_state.hpp"

#include <algorithm>

#include "viz/opencv_image.hpp"

namespace scantrace::viz {

CanvasState::CanvasState(cv::Rect window)
    : window_(window),
      image_(std::max(window.height, 1), std::max(window.width, 1), CV_8UC3, cv::Scalar::all(0)),
      mask_(std::max(window.height, 1), std::max(window.width, 1), CV_8UC1, cv::Scalar::all(0)) {}

CanvasState CanvasState::clone() const {
  CanvasState c = *this;
  c.image_ = image_.clone();
  c.mask_ = mask_.clone();
  return c;
}

bool CanvasState::written(std::int64_t x, std::int64_t y) const {
  if (x < window_.x || y < window_.y || x >= window_.x + window_.width ||
      y >= window_.y + window_.height)
    return false;
  return mask_.at<std::uint8_t>(static_cast<int>(y - window_.y), static_cast<int>(x - window_.x)) !=
         0;
}

cv::Vec3b CanvasState::bgr(std::int64_t x, std::int64_t y) const {
  if (!written(x, y)) return {};
  return image_.at<cv::Vec3b>(static_cast<int>(y - window_.y), static_cast<int>(x - window_.x));
}

void CanvasState::put(std::int64_t x, std::int64_t y, const Color& c) {
  ++writes_;
  if (x < window_.x || y < window_.y || x >= window_.x + window_.width ||
      y >= window_.y + window_.height)
    return;
  const int row = static_cast<int>(y - window_.y), col = static_cast<int>(x - window_.x);
  std::uint8_t& m = mask_.at<std::uint8_t>(row, col);
  if (m) ++overwrites_;
  m = 255;
  image_.at<cv::Vec3b>(row, col) =
      cv::Vec3b(to_byte(static_cast<float>(c.b)), to_byte(static_cast<float>(c.g)),
                to_byte(static_cast<float>(c.r)));
}

Color span_pixel_colour(const trace::Scanline& s, const std::optional<Color>& flat,
                        std::int64_t x) {
  if (!s.span_colors) return flat.value_or(Color{});
  const std::int64_t last = s.span->x_end - 1 - s.span->x_begin;
  const double w = last > 0 ? static_cast<double>(x - s.span->x_begin) / last : 0.0;
  return s.span_colors->begin + (s.span_colors->end - s.span_colors->begin) * w;
}

void CanvasState::paint_scanline(const trace::Trace& trace, const trace::Scanline& s) {
  if (!s.span || s.span->size() <= 0) return;
  std::optional<Color> flat;
  try {
    flat = trace.triangle_begin(s.triangle).flat_color;
  } catch (const std::out_of_range&) {
  }
  if (s.intervals) {
    // A general polygon's row: each inside interval is a span of its own.
    for (const trace::Interval& iv : *s.intervals) {
      trace::Scanline one;
      one.span = iv.pixels;
      one.span_colors = iv.colors;
      for (std::int64_t x = iv.pixels.x_begin; x < iv.pixels.x_end; ++x)
        put(x, s.y, span_pixel_colour(one, flat, x));
    }
    return;
  }
  for (std::int64_t x = s.span->x_begin; x < s.span->x_end; ++x)
    put(x, s.y, span_pixel_colour(s, flat, x));
}

void CanvasState::paint_rows(const trace::Trace& trace, int triangle, std::int64_t first_row,
                             std::int64_t last_row) {
  if (!trace.has_triangle(triangle)) return;
  // Pixel events, when present, are the record of what was written; a row without them (a trace
  // cut short by --max-events) falls back to its span.
  std::vector<std::int64_t> rows_with_pixels;
  for (const trace::Pixel* p : trace.pixels(triangle))
    if (p->y >= first_row && p->y <= last_row) {
      // A pixel the z-buffer rejected is narrated but was not written.
      if (!p->depth_test || p->depth_test->passed) put(p->x, p->y, p->color);
      if (rows_with_pixels.empty() || rows_with_pixels.back() != p->y)
        rows_with_pixels.push_back(p->y);
    }
  for (const trace::Scanline* s : trace.scanlines(triangle))
    if (s->y >= first_row && s->y <= last_row &&
        std::find(rows_with_pixels.begin(), rows_with_pixels.end(), s->y) == rows_with_pixels.end())
      paint_scanline(trace, *s);
}

void CanvasState::paint_triangle(const trace::Trace& trace, int triangle) {
  paint_rows(trace, triangle, INT64_MIN, INT64_MAX);
}

}  // namespace scantrace::viz
