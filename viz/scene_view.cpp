#include "viz/scene_view.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <spdlog/fmt/fmt.h>

#include "viz/cards.hpp"
#include "viz/grid_view.hpp"
#include "viz/palette.hpp"
#include "viz/panel_writer.hpp"
#include "viz/text_format.hpp"
#include "viz/trace_lookup.hpp"

namespace scantrace::viz {
namespace {

// Batches longer than this list their last rows only: the highlighted triangle and its
// predecessors are what the frame is about.
constexpr std::size_t kListedTriangles = 6;

std::string depth_text(const std::optional<double>& d) {
  return d ? display_number(*d, 3) : "-";
}

// A bar from the farthest depth (left) to the nearest (right), filled up to the depth reached.
void depth_bar(PanelWriter& w, const Typography& type, const SceneSummary& scene,
               const std::optional<double>& current) {
  FrameView& frame = w.canvas();
  if (!scene.min_depth || !scene.max_depth) return;
  const double far = *scene.max_depth, near = *scene.min_depth;
  const int h = type.px(12);
  const Rect bar(w.left(), w.y(), w.width(), h);
  frame.rectangle(bar, palette::kPanelBorder, FILLED);
  if (current) {
    const double f = far > near ? (far - *current) / (far - near) : 1.0;
    const int x = bar.x + static_cast<int>(std::clamp(f, 0.0, 1.0) * bar.width);
    frame.rectangle({bar.x, bar.y, x - bar.x, h}, palette::kCurrentTriangle, FILLED);
    frame.line({x, bar.y - type.px(3)}, {x, bar.y + h + type.px(3)}, palette::kText, type.px(2));
  }
  frame.rectangle(bar, palette::kMutedText, 1);
  w.gap(16);
  const std::string left = fmt::format("far: depth {}", display_number(far, 3));
  const std::string right = fmt::format("near: depth {}", display_number(near, 3));
  type.draw(frame, left, {w.left(), w.y()}, TextStyle::small, palette::kMutedText);
  type.draw(frame, right, {w.left() + w.width() - type.width(right, TextStyle::small), w.y()},
            TextStyle::small, palette::kMutedText);
  w.move_to(w.y() + type.line_height(TextStyle::small));
}

}  // namespace

SceneSummary summarize_scene(const trace::Trace& trace, const StepPlan& plan) {
  SceneSummary s;
  for (int t : plan.order) {
    const trace::TriangleBegin* b = find_begin(trace, t);
    s.depth.push_back(b ? b->depth : std::nullopt);
    if (b && b->depth) {
      s.min_depth = std::min(s.min_depth.value_or(*b->depth), *b->depth);
      s.max_depth = std::max(s.max_depth.value_or(*b->depth), *b->depth);
    }
    if (trace.skipped(t)) ++s.skipped;
    if (const auto end = trace.triangle_end(t)) s.pixels += end->pixels;
  }
  return s;
}

void draw_scene_view(FrameView& frame, const ViewGeometry& geometry, const Typography& type,
                     Size canvas, const CanvasState& state, const trace::Trace& trace,
                     const StepPlan& plan, const Step& step) {
  GridView view(frame, geometry, type, canvas);
  view.cells(state);
  view.grid();
  // Z-buffer: the pixels this step's triangles did not write because something nearer was already
  // there, crossed out (when cells are big enough to hold a mark).
  if (state.depth_test() && geometry.cell() >= 5) {
    const int r = std::max(1, static_cast<int>(geometry.cell() * 0.3));
    for (const Point& p : state.recent_rejections()) {
      const Point2d c = geometry.to_frame(p.x, p.y);
      const Point q(static_cast<int>(std::lround(c.x)), static_cast<int>(std::lround(c.y)));
      if (!geometry.view().contains(q)) continue;
      frame.line(q + Point(-r, -r), q + Point(r, r), palette::kRejected, 1);
      frame.line(q + Point(-r, r), q + Point(r, -r), palette::kRejected, 1);
    }
  }
  if (step.kind != StepKind::painter_batch) return;
  for (std::size_t i = step.first; i <= step.last && i < plan.order.size(); ++i)
    if (const trace::TriangleBegin* b = find_begin(trace, plan.order[i]);
        b && plan.order[i] != step.triangle)
      view.outline(polygon_of(*b), palette::kBatchOutline, 1);
  if (const trace::TriangleBegin* b = find_begin(trace, step.triangle)) {
    const std::vector<Vec2>& p = polygon_of(*b);
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2 a = p[i], c = p[(i + 1) % p.size()];
      draw_segment_with_halo(frame, geometry.to_frame(a.x, a.y), geometry.to_frame(c.x, c.y),
                             geometry.view(), palette::kCurrentTriangle, type.px(3), palette::kHalo,
                             type.px(1));
    }
  }
}

namespace {

// The panel's heading: the finished image, or which triangles of the order this step draws.
void scene_panel_heading(PanelWriter& w, const Step& step, std::size_t n, bool zbuffer,
                         const SceneSummary& scene) {
  const char* order = zbuffer ? "scene order" : "drawing order";
  if (step.kind == StepKind::scene_done) {
    w.heading("The finished image");
    w.paragraph(fmt::format("{} triangles drawn, {} skipped.",
                            integer(static_cast<std::int64_t>(n - scene.skipped)),
                            integer(static_cast<std::int64_t>(scene.skipped))));
    return;
  }
  w.heading(zbuffer ? "Z-buffer: a depth test per pixel" : "Painter's algorithm: far to near");
  const auto count = [](std::size_t v) { return integer(static_cast<std::int64_t>(v)); };
  // Positions in the order drawn, 1-based; the table below lists the faces by their index.
  w.line(step.first == step.last
             ? fmt::format("Drawn: number {} of {} in {}", count(step.first + 1), count(n), order)
             : fmt::format("Drawn: numbers {} .. {} of {} in {}", count(step.first + 1),
                           count(step.last + 1), count(n), order),
         TextStyle::strong);
}

// How the scene's triangles are ordered (a depth test, or the painter's sort with its depth bar).
void scene_panel_method(PanelWriter& w, const Typography& type, const SceneSummary& scene,
                        const Step& step, bool zbuffer) {
  if (zbuffer) {
    w.paragraph(
        "The triangles are drawn in the order of the scene. At every pixel a triangle covers, "
        "its depth there (the plane through its snapped vertices and their depths) is compared "
        "with the depth stored for that pixel: if nearer (smaller), the pixel is written and its "
        "depth stored; otherwise it is rejected (x). Equal depths keep the first triangle.");
    return;
  }
  w.paragraph(
      "A triangle's depth is the mean of its three vertex depths. The largest depth (farthest) "
      "is drawn first; nearer triangles come later and paint over what lies behind them. Equal "
      "depths keep the order of the faces.");
  w.gap(8);
  const std::optional<double> current =
      step.kind == StepKind::painter_batch && step.last < scene.depth.size()
          ? scene.depth[step.last]
          : scene.min_depth;
  depth_bar(w, type, scene, current);
}

// A painter's batch: the highlighted face, then the batch's last triangles as a table.
void scene_panel_batch(PanelWriter& w, const trace::Trace& trace, const StepPlan& plan,
                       const SceneSummary& scene, const Step& step) {
  const std::size_t n = plan.order.size();
  if (const trace::TriangleBegin* b = find_begin(trace, step.triangle)) {
    w.line(b->depth ? fmt::format("Highlighted: face {}, depth {}", step.triangle,
                                  display_number(*b->depth, 4))
                    : fmt::format("Highlighted: face {}", step.triangle),
           TextStyle::strong);
    std::string vs = "vertices";
    for (const Vec2& v : b->vertices) {
      vs += "  ";
      vs += point(v, 1);
    }
    w.line(vs);
    for (std::size_t i = 0; i < b->colors.size(); ++i)
      w.swatch(b->colors[i], fmt::format("v{}  {}", i, colour(b->colors[i])), TextStyle::small);
    w.gap(6);
  }
  std::vector<TableRow> rows;
  const std::size_t first = step.last + 1 - step.first > kListedTriangles
                                ? step.last + 1 - kListedTriangles
                                : step.first;
  if (first > step.first)
    w.line(fmt::format("... {} more triangles earlier in this step",
                       integer(static_cast<std::int64_t>(first - step.first))),
           TextStyle::small, palette::kMutedText);
  for (std::size_t i = first; i <= step.last && i < n; ++i) {
    const int t = plan.order[i];
    TableRow r;
    const auto end = trace.triangle_end(t);
    const auto skipped = trace.skipped(t);
    r.cells = {std::to_string(t), depth_text(scene.depth[i]), end ? integer(end->rows) : "-",
               skipped ? skipped->reason
               : end   ? integer(end->pixels)
                       : "-"};
    r.highlighted = t == step.triangle;
    r.muted = skipped.has_value();
    rows.push_back(r);
  }
  w.table({{"face"}, {"depth"}, {"rows"}, {"pixels"}}, rows);
  w.gap(8);
}

// The pixels written so far (and rejected, or written over) and the method's formulas.
void scene_panel_counts(PanelWriter& w, bool zbuffer, const CanvasState& state) {
  if (zbuffer) {
    w.line(fmt::format("Pixels written (depth test passed): {}", integer(state.writes())),
           TextStyle::body);
    w.line(fmt::format("Pixels rejected (something nearer there): {}", integer(state.rejected())),
           TextStyle::body);
    w.gap(8);
    w.formula({"depth(x, y) = d0 + a (x - x0) + b (y - y0)",
               "write if depth(x, y) < stored(x, y), then stored(x, y) = depth(x, y)",
               "triangles in scene order, no sort"});
    return;
  }
  w.line(fmt::format("Pixels written so far: {}", integer(state.writes())), TextStyle::body);
  w.line(fmt::format("of them over a farther triangle's pixel: {}", integer(state.overwrites())),
         TextStyle::body);
  w.gap(8);
  w.formula({"depth(T) = (z0 + z1 + z2) / 3", "draw in order of decreasing depth (stable sort)",
             "each triangle: the edge-table scanline fill"});
}

}  // namespace

void draw_scene_panel(FrameView& frame, const Rect& area, const Typography& type,
                      const trace::Trace& trace, const StepPlan& plan, const SceneSummary& scene,
                      const Step& step, const CanvasState& state) {
  PanelWriter w(frame, area, type);
  const bool zbuffer = uses_zbuffer(trace.header());
  scene_panel_heading(w, step, plan.order.size(), zbuffer, scene);
  w.gap(6);
  scene_panel_method(w, type, scene, step, zbuffer);
  w.gap(8);
  if (step.kind == StepKind::painter_batch) scene_panel_batch(w, trace, plan, scene, step);
  if (trace.header().level == TraceLevel::triangle)
    w.paragraph(
        "This trace holds no scanlines (level triangle): the pixels shown are filled again "
        "from each triangle's recorded vertices and colours by the same fill.",
        TextStyle::small, palette::kMutedText);
  scene_panel_counts(w, zbuffer, state);
}

}  // namespace scantrace::viz
