#include "viz/frame_composer.hpp"

#include <algorithm>
#include <cmath>

#include <spdlog/fmt/fmt.h>

#include "viz/grid_view.hpp"
#include "viz/legend.hpp"
#include "viz/palette.hpp"
#include "viz/side_panel.hpp"
#include "viz/text_format.hpp"
#include "viz/trace_lookup.hpp"
#include "viz/zoom_inset.hpp"

namespace scantrace::viz {
namespace {

PixelBox whole_canvas(const trace::Trace& t) {
  return {0, 0, std::max(0, t.header().canvas.width - 1),
          std::max(0, t.header().canvas.height - 1)};
}

std::string counter(const Step& step, std::size_t index, std::size_t steps) {
  std::string s;
  if (step.kind == StepKind::scanlines)
    s = step.first_number == step.last_number
            ? fmt::format("scanline {} of {}     ", step.last_number, step.scanline_count)
            : fmt::format("scanlines {}-{} of {}     ", step.first_number, step.last_number,
                          step.scanline_count);
  return s + fmt::format("step {} / {}", index + 1, steps);
}

}  // namespace

PixelBox triangle_region(const trace::Trace& trace, int triangle) {
  const trace::TriangleBegin* b = find_begin(trace, triangle);
  const PixelBox canvas = whole_canvas(trace);
  if (!b || polygon_of(*b).empty()) return canvas;
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (const Vec2& v : polygon_of(*b)) {
    x0 = std::min(x0, v.x), x1 = std::max(x1, v.x);
    y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
  }
  // Clamp in double first: a vertex at 1e9 must not overflow the integer box.
  auto clamp_to = [](double v, std::int64_t lo, std::int64_t hi) {
    return static_cast<std::int64_t>(
        std::clamp(v, static_cast<double>(lo), static_cast<double>(hi)));
  };
  PixelBox r{clamp_to(std::floor(x0), 0, canvas.x1), clamp_to(std::floor(y0), 0, canvas.y1),
             clamp_to(std::ceil(x1), 0, canvas.x1), clamp_to(std::ceil(y1), 0, canvas.y1)};
  if (r.empty()) return canvas;
  const std::int64_t margin =
      std::max<std::int64_t>(1, std::llround(0.08 * std::max(r.width(), r.height())));
  return {r.x0 - margin, r.y0 - margin, r.x1 + margin, r.y1 + margin};
}

FrameComposer::FrameComposer(const trace::Trace& trace, const StepPlan& plan, Size frame,
                             std::string source)
    : trace_(trace),
      plan_(plan),
      size_(frame),
      canvas_(trace.header().canvas.width, trace.header().canvas.height),
      type_(frame),
      layout_(FrameLayout::for_frame(frame, type_)),
      source_(std::move(source)),
      scene_region_(whole_canvas(trace)) {
  if (plan.mode == ReplayMode::scene) scene_ = summarize_scene(trace, plan);
}

void FrameComposer::mark(std::optional<CanvasPixel> pixel) {
  marked_ = pixel;
  scene_region_ = whole_canvas(trace_);
  if (!pixel) return;
  // The traced faces' own views, united, and the pixel (which a face may only touch).
  PixelBox r{pixel->x, pixel->y, pixel->x, pixel->y};
  for (int t : plan_.order) {
    const PixelBox b = triangle_region(trace_, t);
    r = {std::min(r.x0, b.x0), std::min(r.y0, b.y0), std::max(r.x1, b.x1), std::max(r.y1, b.y1)};
  }
  const PixelBox canvas = whole_canvas(trace_);
  scene_region_ = {std::max(r.x0, canvas.x0), std::max(r.y0, canvas.y0),
                   std::min(r.x1, canvas.x1), std::min(r.y1, canvas.y1)};
  if (scene_region_.empty()) scene_region_ = canvas;  // the pixel is off the canvas
}

std::optional<ViewGeometry> FrameComposer::geometry(const Step& step) const {
  const double max_cell = layout_.view.height / 8.0;
  switch (step.kind) {
    case StepKind::title:
    case StepKind::end: {
      // The cards' picture: the one triangle of a single-triangle replay, else the canvas.
      const Rect area = card_picture_area(size_, type_);
      const bool one = plan_.mode == ReplayMode::triangles && plan_.order.size() == 1;
      return ViewGeometry(area,
                          one ? triangle_region(trace_, plan_.order.front()) : scene_region_,
                          area.height / 8.0);
    }
    case StepKind::painter_batch:
    case StepKind::scene_done:
      return ViewGeometry(layout_.view, scene_region_, max_cell);
    default:
      return ViewGeometry(layout_.view, triangle_region(trace_, step.triangle), max_cell);
  }
}

void FrameComposer::title_bar(FrameView& frame, const Step& step, std::size_t index) const {
  const Rect& bar = layout_.title_bar;
  frame.rectangle(bar, palette::kTitleBar, FILLED);
  const int m = layout_.margin;
  const int top = bar.y + (bar.height - type_.measure("A", TextStyle::heading).height) / 2;
  int x = type_.draw(frame, "scantrace", {m, top}, TextStyle::heading, palette::kTitleText);
  const trace::Header& h = trace_.header();
  const std::string context =
      plan_.mode == ReplayMode::scene
          ? fmt::format("{}, {} triangles   |   {} shading, {} rule",
                        uses_zbuffer(h) ? "z-buffer" : "painter's algorithm",
                        integer(static_cast<std::int64_t>(plan_.order.size())),
                        to_string(h.shading), to_string(h.fill_rule))
      : h.winding_rule
          ? fmt::format("polygon {}   |   {} shading, {} rule, {} winding", step.triangle,
                        to_string(h.shading), to_string(h.fill_rule), to_string(*h.winding_rule))
          : fmt::format("triangle {}   |   {} shading, {} rule", step.triangle,
                        to_string(h.shading), to_string(h.fill_rule));
  type_.draw(frame, context, {x + type_.px(18), top + type_.px(2)}, TextStyle::body,
             palette::kTitleText);
  const std::string right = counter(step, index, plan_.steps.size());
  type_.draw(frame, right,
             {bar.width - m - type_.width(right, TextStyle::strong), top + type_.px(2)},
             TextStyle::strong, palette::kTitleText);
}

void FrameComposer::triangle_frame(FrameView& frame, const Step& step, const CanvasState& state,
                                   std::vector<PlacedBox>* placed) const {
  const ViewGeometry g = *geometry(step);
  GridView view(frame, g, type_, canvas_);
  view.cells(state);
  view.grid();
  const trace::TriangleBegin* b = find_begin(trace_, step.triangle);
  const trace::EdgeTableEvent* table = find_edge_table(trace_, step.triangle);
  const trace::Scanline* row = step.kind == StepKind::scanlines
                                   ? find_scanline(trace_, step.triangle, step.last_row)
                                   : nullptr;
  if (b) view.outline(*b, palette::kOutline, step.kind == StepKind::scanlines ? 1 : 2);
  if (table && step.kind == StepKind::edge_table_entry) {
    const int n = static_cast<int>(table->edges.size());
    for (int i = 0; i <= step.entry && i < n; ++i)
      view.edge(table->edges[i].from, table->edges[i].to, table->edges[i].edge, i == step.entry);
    if (step.entry >= n) {
      const trace::HorizontalEntry& hz = table->horizontal[step.entry - n];
      view.edge(hz.from, hz.to, hz.edge, true);
    }
  }
  if (row) {
    view.scanline(row->y);
    for (const trace::EdgeCrossing& a : row->active_edges)
      if (const trace::EdgeEntry* e = find_edge(table, a.edge))
        view.edge(e->from, e->to, e->edge, true);
    view.spans(*row);
  }
  // Markers first, then the labels that matter most for the step: the row's x values, its y,
  // the vertices; the zoom insets go where none of them is.
  if (b) view.vertex_markers(*b);
  if (row) {
    view.active_point_markers(*row);
    view.active_point_labels(*row);
    view.scanline_label(row->y);
  }
  if (b) view.vertex_labels(*b);
  std::vector<PlacedBox> insets;
  if (row && !view.grid_visible())
    insets = draw_zoom_insets(frame, g, type_, canvas_, state, b, table, *row, view.placement());
  frame.rectangle(g.view(), palette::kPanelBorder, 1);
  if (placed) {
    *placed = view.placement().boxes();
    placed->insert(placed->end(), insets.begin(), insets.end());
  }

  LegendShape shape;  // a polygon's legend names its outline and all of its edges
  shape.ringed_pixel = marked_.has_value();
  if (b && trace_.header().winding_rule) {
    shape.polygon = true;
    shape.edges = static_cast<int>(polygon_of(*b).size());
  }
  const int legend = legend_height(type_, LegendKind::triangle, shape);
  Rect text = layout_.panel;
  text.height -= legend;
  draw_triangle_panel(frame, text, type_, trace_, step);
  draw_legend(frame, layout_.panel, type_, LegendKind::triangle, shape);
}

void FrameComposer::scene_frame(FrameView& frame, const Step& step,
                                const CanvasState& state) const {
  const ViewGeometry g = *geometry(step);
  draw_scene_view(frame, g, type_, canvas_, state, trace_, plan_, step);
  frame.rectangle(g.view(), palette::kPanelBorder, 1);
  LegendShape shape;
  shape.ringed_pixel = marked_.has_value();
  const int legend = legend_height(type_, LegendKind::scene, shape);
  Rect text = layout_.panel;
  text.height -= legend;
  draw_scene_panel(frame, text, type_, trace_, plan_, scene_, step, state);
  draw_legend(frame, layout_.panel, type_, LegendKind::scene, shape);
}

void FrameComposer::card_picture(FrameView& frame, const Step& step, const CanvasState& state,
                                 std::vector<PlacedBox>* placed) const {
  const Rect area = card_picture_area(size_, type_);
  const bool one = plan_.mode == ReplayMode::triangles && plan_.order.size() == 1;
  const ViewGeometry g = *geometry(step);
  GridView view(frame, g, type_, canvas_);
  // The end card shows the finished image as rendered: unwritten pixels in the background colour.
  if (step.kind == StepKind::end)
    view.cells(state, trace_.header().background);
  else
    view.cells(state);
  view.grid();
  // Outlines on the title card say what is coming; the end card shows the result as it is. Past
  // a few thousand triangles outlines are only noise.
  constexpr std::size_t kMaxOutlines = 3000;
  if (step.kind == StepKind::title && plan_.order.size() <= kMaxOutlines)
    for (int t : plan_.order)
      if (const trace::TriangleBegin* b = find_begin(trace_, t))
        view.outline(*b, palette::kOutline, one ? 2 : 1);
  if (one)
    if (const trace::TriangleBegin* b = find_begin(trace_, plan_.order.front())) view.vertices(*b);
  frame.rectangle(area, palette::kPanelBorder, 1);
  if (placed) *placed = view.placement().boxes();
}

Frame FrameComposer::compose(const Step& step, std::size_t index, const CanvasState& state,
                             std::vector<PlacedBox>* placed) const {
  Frame result(size_, palette::kFrame);
  FrameView frame(result);
  if (placed) placed->clear();
  CardInfo info{source_, plan_.rows_per_step, state.writes(), state.overwrites(), state.rejected()};
  switch (step.kind) {
    case StepKind::title:
      draw_title_card(frame, type_, trace_, plan_, info);
      card_picture(frame, step, state, placed);
      return result;
    case StepKind::end:
      draw_end_card(frame, type_, trace_, plan_, info);
      card_picture(frame, step, state, placed);
      return result;
    case StepKind::painter_batch:
    case StepKind::scene_done:
      title_bar(frame, step, index);
      scene_frame(frame, step, state);
      return result;
    default:
      title_bar(frame, step, index);
      triangle_frame(frame, step, state, placed);
      return result;
  }
}

}  // namespace scantrace::viz
