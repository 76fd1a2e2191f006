#include "viz/legend.hpp"

#include <functional>
#include <string>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "viz/palette.hpp"
#include "viz/view_geometry.hpp"

namespace scantrace::viz {
namespace {

using Icon = std::function<void(FrameView&, const Rect&, const Typography&)>;

struct Entry {
  Icon icon;
  std::string text;
};

Point2d mid_left(const Rect& r) {
  return {static_cast<double>(r.x), r.y + r.height / 2.0};
}
Point2d mid_right(const Rect& r) {
  return {static_cast<double>(r.x + r.width), r.y + r.height / 2.0};
}

void line_icon(FrameView& f, const Rect& r, const Scalar& c, int thickness, int halo) {
  if (halo > 0)
    draw_segment_with_halo(f, mid_left(r), mid_right(r), r, c, thickness, palette::kHalo, halo);
  else
    draw_segment(f, mid_left(r), mid_right(r), r, c, thickness);
}

// "e0, e1, e2" for a triangle; a polygon's edges by their range ("e0 .. e4"), as many as it has.
std::string edge_names(LegendShape shape) {
  if (shape.edges <= 3) return "e0, e1, e2";
  return fmt::format("e0 .. e{}", shape.edges - 1);  // ASCII: the frame font has no "…"
}

std::vector<Entry> entries(LegendKind kind, LegendShape shape = {}) {
  std::vector<Entry> e;
  auto cells = [](FrameView& f, const Rect& r, const Typography&) {
    const int s = r.height;
    f.rectangle({r.x, r.y, s, s}, Scalar(60, 60, 230), FILLED);
    f.rectangle({r.x + s, r.y, s, s}, palette::kEmptyCell, FILLED);
    f.rectangle({r.x, r.y, 2 * s, s}, palette::kGridLine, 1);
    f.line({r.x + s, r.y}, {r.x + s, r.y + s - 1}, palette::kGridLine, 1);
  };
  auto outside = [](FrameView& f, const Rect& r, const Typography&) {
    f.rectangle({r.x, r.y, 2 * r.height, r.height}, palette::kOutsideCanvas, FILLED);
  };
  if (kind == LegendKind::triangle) {
    e.push_back({[](FrameView& f, const Rect& r, const Typography& t) {
                   line_icon(f, r, palette::kOutline, t.px(2), 0);
                 },
                 shape.polygon ? "polygon outline (snapped)" : "triangle outline (snapped)"});
    e.push_back({[](FrameView& f, const Rect& r, const Typography& t) {
                   line_icon(f, r, palette::kScanline, t.px(2), t.px(1));
                 },
                 "current scanline"});
    e.push_back({[](FrameView& f, const Rect& r, const Typography& t) {
                   for (int i = 0; i < 3; ++i) {
                     const Rect part(r.x + i * r.width / 3, r.y, r.width / 3 - t.px(2), r.height);
                     line_icon(f, part, palette::edge_colour(i), t.px(3), t.px(1));
                   }
                 },
                 "edges " + edge_names(shape) + " (bold: active)"});
    e.push_back({[](FrameView& f, const Rect& r, const Typography& t) {
                   const Point c(r.x + r.height / 2 + t.px(2), r.y + r.height / 2);
                   f.circle(c, r.height / 2, palette::edge_colour(0), FILLED, LINE_AA);
                   f.circle(c, r.height / 2 - t.px(2), Scalar(60, 60, 230), FILLED, LINE_AA);
                 },
                 "active point: edge meets row, x"});
    e.push_back({[](FrameView& f, const Rect& r, const Typography& t) {
                   const Rect box(r.x + t.px(2), r.y + t.px(2), r.width - t.px(4),
                                  r.height - t.px(4));
                   f.rectangle(box, palette::kHalo, t.px(4));
                   f.rectangle(box, palette::kSpan, t.px(2));
                 },
                 "span: the pixels of this row"});
    e.push_back({[](FrameView& f, const Rect& r, const Typography& t) {
                   const Point c(r.x + r.height / 2 + t.px(2), r.y + r.height / 2);
                   f.circle(c, r.height / 2, palette::kHalo, FILLED, LINE_AA);
                   f.circle(c, r.height / 2 - t.px(2), Scalar(0, 0, 255), FILLED, LINE_AA);
                 },
                 "vertex, in its colour"});
    e.push_back({cells, "pixel filled (final colour) / not"});
    e.push_back({[](FrameView& f, const Rect& r, const Typography& t) {
                   const int s = r.height;
                   for (int i = 0; i < 2; ++i) {
                     f.rectangle({r.x + i * s, r.y, s + 1, s}, palette::kGridLine, 1);
                     f.circle({r.x + i * s + s / 2, r.y + s / 2}, std::max(1, t.px(1.5)),
                              palette::kCentreOnLight, FILLED, LINE_AA);
                   }
                 },
                 "pixel grid and centres (big cells)"});
    e.push_back({outside, "outside the canvas"});
  } else {
    e.push_back({[](FrameView& f, const Rect& r, const Typography& t) {
                   line_icon(f, r, palette::kCurrentTriangle, t.px(3), t.px(1));
                 },
                 "triangle drawn last (highlighted)"});
    e.push_back({[](FrameView& f, const Rect& r, const Typography& t) {
                   line_icon(f, r, palette::kBatchOutline, t.px(1), 0);
                 },
                 "the other triangles of this step"});
    e.push_back({cells, "pixels drawn so far / background"});
    e.push_back({outside, "outside the canvas"});
  }
  if (shape.ringed_pixel)
    e.push_back({[](FrameView& f, const Rect& r, const Typography& t) {
                   const int s = r.height;
                   const Rect ring(r.x + t.px(2), r.y, s, s);
                   f.rectangle(ring, palette::kHalo, 4);
                   f.rectangle(ring, palette::kSelection, 2);
                 },
                 "the pixel asked about (why X Y)"});
  return e;
}

}  // namespace

std::vector<std::string> legend_texts(LegendKind kind, LegendShape shape) {
  std::vector<std::string> texts;
  for (const Entry& e : entries(kind, shape)) texts.push_back(e.text);
  return texts;
}

int legend_height(const Typography& type, LegendKind kind, LegendShape shape) {
  const int rows = (static_cast<int>(entries(kind, shape).size()) + 1) / 2;
  return type.line_height(TextStyle::small) * (rows + 1) + type.px(6);
}

void draw_legend(FrameView& frame, const Rect& area, const Typography& type, LegendKind kind,
                 LegendShape shape) {
  const std::vector<Entry> list = entries(kind, shape);
  const int h = legend_height(type, kind, shape);
  int y = area.y + area.height - h;
  frame.line({area.x, y}, {area.x + area.width, y}, palette::kPanelBorder, 1);
  y += type.px(6);
  type.draw(frame, "Legend", {area.x, y}, TextStyle::small, palette::kMutedText);
  y += type.line_height(TextStyle::small);
  const int line = type.line_height(TextStyle::small);
  const int icon_h = line - type.px(6), icon_w = type.px(34);
  const int column = area.width / 2;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const int x = area.x + static_cast<int>(i % 2) * column;
    const int top = y + static_cast<int>(i / 2) * line;
    list[i].icon(frame, {x, top, icon_w, icon_h}, type);
    type.draw(frame, list[i].text, {x + icon_w + type.px(8), top}, TextStyle::small,
              palette::kText);
  }
}

}  // namespace scantrace::viz
