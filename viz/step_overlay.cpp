#include "viz/step_overlay.hpp"

#include <algorithm>
#include <cmath>

#include <spdlog/fmt/fmt.h>

#include "viz/palette.hpp"
#include "viz/trace_lookup.hpp"

namespace scantrace::viz {
namespace {

using palette::kSelection;

std::string colour_text(const Color& c) {
  auto byte = [](double v) { return static_cast<int>(std::lround(255 * std::clamp(v, 0.0, 1.0))); };
  return fmt::format("({:.3f}, {:.3f}, {:.3f}) = #{:02x}{:02x}{:02x}", c.r, c.g, c.b, byte(c.r),
                     byte(c.g), byte(c.b));
}

// Whether step `index` of the plan has reached the write of `triangle` on row `y`: the row was in
// a scanline step of that triangle, or the triangle in a painter's batch, at or before `index`.
bool written_by_step(const StepPlan& plan, std::size_t index, int triangle, std::int64_t y) {
  for (std::size_t i = 0; i <= index && i < plan.steps.size(); ++i) {
    const Step& s = plan.steps[i];
    if (s.kind == StepKind::scanlines && s.triangle == triangle && s.first_row <= y &&
        y <= s.last_row)
      return true;
    if (s.kind == StepKind::painter_batch)
      for (std::size_t k = s.first; k <= s.last && k < plan.order.size(); ++k)
        if (plan.order[k] == triangle) return true;
  }
  return false;
}

}  // namespace

std::optional<CanvasPixel> pixel_at(const ViewGeometry& g, Point p, Size canvas) {
  if (!g.view().contains(p)) return std::nullopt;
  const CanvasPixel px{g.pixel_x(p.x), g.pixel_y(p.y)};
  if (px.x < 0 || px.y < 0 || px.x >= canvas.width || px.y >= canvas.height) return std::nullopt;
  return px;
}

void mark_pixel(FrameView& frame, const ViewGeometry& g, CanvasPixel p) {
  const Point2d a = g.to_frame(p.x - 0.5, p.y - 0.5), b = g.to_frame(p.x + 0.5, p.y + 0.5);
  const Point2d c = (a + b) * 0.5;
  // Small cells get a ring larger than the cell, so the pixel stays findable.
  const double half = std::max((b.x - a.x) / 2 + 2, 6.0);
  const Rect ring(
      Point(static_cast<int>(std::floor(c.x - half)), static_cast<int>(std::floor(c.y - half))),
      Point(static_cast<int>(std::ceil(c.x + half)), static_cast<int>(std::ceil(c.y + half))));
  FrameView view = frame(g.view() & Rect(0, 0, frame.width(), frame.height()));
  const Rect local = ring - g.view().tl();
  view.rectangle(local, palette::kHalo, 4);
  view.rectangle(local, kSelection, 2);
}

std::vector<std::string> pixel_history_lines(const trace::Trace& trace, const StepPlan& plan,
                                             std::size_t index, CanvasPixel p) {
  std::vector<std::string> lines{fmt::format("pixel ({}, {})", p.x, p.y)};
  const trace::PixelHistory h = trace.pixel_history(p.x, p.y);
  const bool scene = plan.mode == ReplayMode::scene;
  std::vector<std::string> writes;
  for (const trace::PixelWrite& w : h.writes) {
    if (!written_by_step(plan, index, w.triangle, p.y)) continue;
    std::string span;
    if (const trace::Scanline* s = find_scanline(trace, w.triangle, p.y); s && s->span)
      span = fmt::format(", span x {}..{}", s->span->x_begin, s->span->x_end - 1);
    writes.push_back(fmt::format("{}. {} {}: row {}{}", writes.size() + 1,
                                 scene ? "face" : "triangle", w.triangle, p.y, span));
    writes.push_back(fmt::format("   colour {}{}", colour_text(w.color),
                                 w.from_pixel_event ? "" : " (from the span)"));
  }
  if (!writes.empty()) {
    lines.push_back(
        fmt::format("written {} time{} so far:", writes.size() / 2, writes.size() == 2 ? "" : "s"));
    lines.insert(lines.end(), writes.begin(), writes.end());
  } else if (h.empty() && trace.header().level == TraceLevel::triangle) {
    lines.push_back("no history: a triangle-level trace has no");
    lines.push_back("scanlines (trace with --level scanline)");
  } else {
    lines.push_back(h.empty() ? "never written in this trace" : "not written yet at this step");
  }
  return lines;
}

void draw_history_box(FrameView& frame, const Rect& area, const Typography& type,
                      const std::vector<std::string>& lines) {
  // The newest writes matter most: when the box would be taller than half the panel, the first
  // writes give way (the header line stays).
  const int line = type.line_height(TextStyle::small), pad = type.px(6);
  const int fit = std::max(2, (area.height / 2 - 2 * pad) / line);
  std::vector<std::string> shown = lines;
  if (static_cast<int>(shown.size()) > fit) {
    const std::size_t cut = shown.size() - static_cast<std::size_t>(fit) + 1;
    shown.erase(shown.begin() + 1, shown.begin() + 1 + static_cast<std::ptrdiff_t>(cut));
    shown.insert(shown.begin() + 1, "...");
  }
  const int h = static_cast<int>(shown.size()) * line + 2 * pad;
  const Rect box(area.x, area.y + area.height - h, area.width, h);
  frame.rectangle(box, palette::kPanel, FILLED);
  frame.rectangle(box, kSelection, 2);
  int y = box.y + pad;
  for (const std::string& s : shown) {
    type.draw(frame, s, {box.x + pad, y}, s == shown.front() ? TextStyle::strong : TextStyle::small,
              palette::kText);
    y += line;
  }
}

void draw_key_help(FrameView& frame, const Typography& type, const std::vector<std::string>& lines) {
  const int line = type.line_height(TextStyle::body), pad = type.px(14);
  int w = 0;
  for (const std::string& s : lines) w = std::max(w, type.width(s, TextStyle::body));
  const Size size(w + 2 * pad, static_cast<int>(lines.size()) * line + 2 * pad);
  const Rect box((frame.width() - size.width) / 2, (frame.height() - size.height) / 2, size.width,
                 size.height);
  frame.rectangle(box, palette::kTitleBar, FILLED);
  frame.rectangle(box, palette::kScanline, 2);
  int y = box.y + pad;
  for (const std::string& s : lines) {
    type.draw(frame, s, {box.x + pad, y}, TextStyle::body, palette::kTitleText);
    y += line;
  }
}

Frame compose_status_strip(int width, int height, const Typography& type, const std::string& left,
                           const std::string& right) {
  Frame frame({width, height}, palette::kTitleBar);
  FrameView strip(frame);
  const int top = (height - type.measure("A", TextStyle::small).height) / 2;
  const int x = type.draw(strip, left, {type.px(10), top}, TextStyle::strong, palette::kTitleText);
  const int rw = type.width(right, TextStyle::small);
  if (width - type.px(10) - rw > x + type.px(20))
    type.draw(strip, right, {width - type.px(10) - rw, top}, TextStyle::small, palette::kTitleText);
  return frame;
}

}  // namespace scantrace::viz
