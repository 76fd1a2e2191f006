#include "viz/canvas_state.hpp"

#include <algorithm>
#include <limits>
#include <span>

#include "src/depth_plane.hpp"
#include "src/image.hpp"
#include "src/scanline_fill.hpp"
#include "src/winding_fill.hpp"

namespace scantrace::viz {
namespace {

// The depth plane of `triangle` when the trace records its vertex depths (z-buffer traces).
// (A bool and an out-parameter rather than an optional: GCC's -Wmaybe-uninitialized misreads
// an optional of this aggregate.)
bool plane_of(const trace::Trace& trace, int triangle, DepthPlane& plane) {
  const trace::TriangleBegin* b = trace.find_triangle_begin(triangle);
  if (!b || b->vertex_depths.size() != 3 || b->snapped.size() != 3) return false;
  plane = DepthPlane::through(b->snapped, b->vertex_depths);
  return true;
}

// What the fill writes to when a triangle-level trace is filled again: the replay's own canvas.
struct StateCanvas {
  CanvasState& state;
  int w, h;
  bool tested = false;
  DepthPlane plane{};

  int width() const { return w; }
  int height() const { return h; }
  void fill_span(int y, int x_begin, int x_end, Color c) {
    for (int x = x_begin; x < x_end; ++x) set(x, y, c);
  }
  void set(int x, int y, Color c) {
    state.put(x, y, c, tested ? std::optional(plane.at(x, y)) : std::nullopt);
  }
};

}  // namespace

CanvasState::CanvasState(Rect window, bool depth_test)
    : window_(window),
      depth_test_(depth_test),
      stride_(std::max(window.width, 1)),
      image_(static_cast<std::size_t>(stride_) * std::max(window.height, 1)),
      mask_(image_.size(), 0) {
  if (depth_test_) depth_.assign(image_.size(), std::numeric_limits<double>::infinity());
}

CanvasState::CanvasState(Rect window, const trace::Trace& trace)
    : CanvasState(window, trace.header().visibility == Visibility::zbuffer) {}

bool CanvasState::inside(std::int64_t x, std::int64_t y) const {
  return x >= window_.x && y >= window_.y && x < window_.x + window_.width &&
         y < window_.y + window_.height;
}

CanvasState CanvasState::clone() const {
  return *this;
}

std::size_t CanvasState::index(std::int64_t x, std::int64_t y) const {
  return static_cast<std::size_t>(y - window_.y) * static_cast<std::size_t>(stride_) +
         static_cast<std::size_t>(x - window_.x);
}

bool CanvasState::written(std::int64_t x, std::int64_t y) const {
  if (!inside(x, y)) return false;
  return mask_[index(x, y)] != 0;
}

const Vec3b* CanvasState::row_pixels(std::int64_t y) const {
  if (y < window_.y || y >= window_.y + window_.height || window_.width <= 0) return nullptr;
  return image_.data() + index(window_.x, y);
}

const std::uint8_t* CanvasState::row_mask(std::int64_t y) const {
  if (y < window_.y || y >= window_.y + window_.height || window_.width <= 0) return nullptr;
  return mask_.data() + index(window_.x, y);
}

Vec3b CanvasState::bgr(std::int64_t x, std::int64_t y) const {
  if (!written(x, y)) return {};
  return image_[index(x, y)];
}

void CanvasState::store(std::int64_t x, std::int64_t y, const Color& c) {
  ++writes_;
  if (!inside(x, y)) return;
  const std::size_t i = index(x, y);
  std::uint8_t& m = mask_[i];
  if (m) ++overwrites_;
  m = 255;
  image_[i] = Vec3b(to_byte(static_cast<float>(c.b)), to_byte(static_cast<float>(c.g)),
                    to_byte(static_cast<float>(c.r)));
}

void CanvasState::reject(std::int64_t x, std::int64_t y) {
  ++rejected_;
  if (inside(x, y)) recent_rejections_.emplace_back(static_cast<int>(x), static_cast<int>(y));
}

void CanvasState::put(std::int64_t x, std::int64_t y, const Color& c, std::optional<double> depth) {
  if (depth_test_ && depth && inside(x, y)) {
    double& z = depth_[index(x, y)];
    // The render's rule (src/zbuffer_canvas.hpp): strictly nearer wins, a tie keeps the first.
    if (!(*depth < z)) {
      reject(x, y);
      return;
    }
    z = *depth;
  }
  store(x, y, c);
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
  if (const trace::TriangleBegin* b = trace.find_triangle_begin(s.triangle)) flat = b->flat_color;
  DepthPlane plane{};
  const bool tested = depth_test_ && plane_of(trace, s.triangle, plane);
  const auto depth = [&](std::int64_t x) {
    return tested ? std::optional(plane.at(static_cast<int>(x), static_cast<int>(s.y)))
                  : std::nullopt;
  };
  if (s.intervals) {
    // A general polygon's row: each inside interval is a span of its own.
    for (const trace::Interval& iv : *s.intervals) {
      trace::Scanline one;
      one.span = iv.pixels;
      one.span_colors = iv.colors;
      for (std::int64_t x = iv.pixels.x_begin; x < iv.pixels.x_end; ++x)
        put(x, s.y, span_pixel_colour(one, flat, x), depth(x));
    }
    return;
  }
  for (std::int64_t x = s.span->x_begin; x < s.span->x_end; ++x)
    put(x, s.y, span_pixel_colour(s, flat, x), depth(x));
}

void CanvasState::paint_rows(const trace::Trace& trace, int triangle, std::int64_t first_row,
                             std::int64_t last_row) {
  if (!trace.has_triangle(triangle)) return;
  // Pixel events, when present, are the record of what was written; a row without them (a trace
  // cut short by --max-events) falls back to its span.
  std::vector<std::int64_t> rows_with_pixels;
  // Only the step's rows are looked up: a frame's cost must not grow with the triangle's size.
  for (const trace::Pixel* p : trace.pixels(triangle, first_row, last_row))
    if (p->y >= first_row && p->y <= last_row) {
      if (!p->depth_test) {
        put(p->x, p->y, p->color);
      } else if (p->depth_test->passed) {
        // The recorded outcome is the truth; the stored depth follows it.
        if (depth_test_ && inside(p->x, p->y)) depth_[index(p->x, p->y)] = p->depth_test->depth;
        store(p->x, p->y, p->color);
      } else {
        reject(p->x, p->y);  // narrated, but not written
      }
      if (rows_with_pixels.empty() || rows_with_pixels.back() != p->y)
        rows_with_pixels.push_back(p->y);
    }
  for (const trace::Scanline* s : trace.scanlines(triangle, first_row, last_row))
    if (s->y >= first_row && s->y <= last_row &&
        std::find(rows_with_pixels.begin(), rows_with_pixels.end(), s->y) == rows_with_pixels.end())
      paint_scanline(trace, *s);
}

void CanvasState::refill(const trace::Trace& trace, int triangle) {
  if (trace.skipped(triangle)) return;
  const trace::TriangleBegin* b = trace.find_triangle_begin(triangle);
  if (!b) return;
  const trace::Header& h = trace.header();
  FillOptions o;
  o.shading = h.shading;
  o.fill_rule = h.fill_rule;
  o.subpixel_bits = h.subpixel_bits;
  // The triangle has a set-up in the trace, so it was not culled: no culling here.
  StateCanvas canvas{*this, h.canvas.width, h.canvas.height};
  canvas.tested = depth_test_ && plane_of(trace, triangle, canvas.plane);
  if (!b->contours.empty()) {
    o.winding_rule = h.winding_rule.value_or(WindingRule::even_odd);
    std::vector<std::vector<Vec2>> contours;
    for (const std::vector<int>& c : b->contours) {
      std::vector<Vec2>& out = contours.emplace_back();
      for (int i : c) out.push_back(b->vertices.at(static_cast<std::size_t>(i)));
    }
    WindingScratch scratch;
    fill_polygon_contours(canvas, std::span<const std::vector<Vec2>>(contours),
                          std::span<const Color>(b->colors), o, scratch);
    return;
  }
  if (h.winding_rule) {
    o.winding_rule = *h.winding_rule;
    const std::vector<std::vector<Vec2>> contours{b->vertices};
    WindingScratch scratch;
    fill_polygon_contours(canvas, std::span<const std::vector<Vec2>>(contours),
                          std::span<const Color>(b->colors), o, scratch);
    return;
  }
  FillScratch scratch;
  fill_polygon(canvas, PolygonInput{b->vertices, b->colors, triangle, b->depth}, o, scratch);
}

void CanvasState::paint_triangle(const trace::Trace& trace, int triangle) {
  if (trace.header().level == TraceLevel::triangle)
    refill(trace, triangle);
  else
    paint_rows(trace, triangle, INT64_MIN, INT64_MAX);
}

}  // namespace scantrace::viz
