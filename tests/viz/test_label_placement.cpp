// Labels and zoom insets never hide what a frame explains (issue 20): on every step of several
// replays, at three frame sizes, no label or inset covers a vertex marker, an active point or
// another label, and every visible vertex and active point has its label, saying the trace's
// numbers. Where the marks are is computed here from the trace through the view's geometry (the
// markers' documented sizes: vertices 7 + 2 design pixels, active points 6 + 2), not taken from
// the placement under test; where the labels and insets were drawn is read from the frame's
// display list (the marks of its operations, issue 32).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "trace/record.hpp"
#include "viz/grid_view.hpp"
#include "viz/replayer.hpp"
#include "viz/trace_lookup.hpp"
#include "viz/typography.hpp"
#include "viz_test_support.hpp"

using namespace scantrace;

namespace {

struct Disc {
  cv::Point2d centre;
  double radius = 0;
  std::string what;
};

bool overlaps(const cv::Rect& r, const Disc& d) {
  // The point of the box nearest the disc's centre, over pixel areas [x, x + width).
  const double nx = std::clamp(d.centre.x, double(r.x), double(r.x + r.width));
  const double ny = std::clamp(d.centre.y, double(r.y), double(r.y + r.height));
  return std::hypot(nx - d.centre.x, ny - d.centre.y) < d.radius;
}

std::string describe(const cv::Rect& r) {
  return fmt::format("[{}, {} {}x{}]", r.x, r.y, r.width, r.height);
}

// What the frame placed, read from its display list's tagged operations: the markers, labels
// and insets (the cells, scanline and span boxes are marks too, but not placed around).
std::vector<viz::PlacedBox> placed_from_marks(const viz::Frame& frame) {
  std::vector<viz::PlacedBox> out;
  for (const viz::Mark& m : frame.marks()) {
    viz::PlacedKind kind;
    switch (m.kind) {
      case viz::MarkKind::vertex:
        kind = viz::PlacedKind::vertex;
        break;
      case viz::MarkKind::active_point:
        kind = viz::PlacedKind::active_point;
        break;
      case viz::MarkKind::label:
        kind = viz::PlacedKind::label;
        break;
      case viz::MarkKind::inset:
        kind = viz::PlacedKind::inset;
        break;
      default:
        continue;
    }
    out.push_back({kind, m.box, m.what, m.layer});
  }
  return out;
}

struct Case {
  std::string name;
  trace::Trace trace;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  auto triangle = [&](std::string name, std::array<Vec2, 3> v, int w, int h) {
    trace::TriangleInput t;
    t.vertices = v;
    t.colors = {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}};
    t.width = w;
    t.height = h;
    out.push_back({std::move(name), test::record(t)});
  };
  // The demo's triangle: cells too small for a grid, so the span's ends get zoom insets.
  triangle("course triangle", {Vec2{20, 20}, Vec2{250, 80}, Vec2{300, 400}}, 512, 512);
  // Thin and slanted: the vertex labels and the x labels crowd along one long diagonal.
  triangle("thin slanted", {Vec2{5.5, 3.2}, Vec2{120.7, 95.1}, Vec2{9.1, 12.4}}, 128, 100);
  // Two vertices a fraction of a pixel apart: their labels compete for the same place.
  triangle("close vertices", {Vec2{10, 10}, Vec2{10.6, 10.3}, Vec2{30, 30}}, 40, 40);
  out.push_back({"small", test::record(test::small_triangle())});
  out.push_back({"medium", test::record(test::medium_triangle())});
  for (WindingRule rule : {WindingRule::even_odd, WindingRule::non_zero}) {
    trace::GeneralPolygonInput p;
    p.contours = {{{10, 1}, {15.5, 18.2}, {1.3, 7.3}, {18.7, 7.3}, {4.5, 18.2}}};
    p.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}};
    p.width = 20;
    p.height = 20;
    FillOptions options;
    options.winding_rule = rule;
    out.push_back({std::string("star ") + to_string(rule), trace::record_polygon(p, options)});
  }
  return out;
}

// The marks a frame's labels must keep off (computed from the trace through the view, with the
// markers' documented sizes) and the label texts (prefixes) it must show: every visible vertex,
// and on a scanline step every visible active point and the row.
struct Expected {
  std::vector<Disc> marks;
  std::vector<std::string> wanted;
};

Expected expected_marks(const viz::ViewGeometry& g, const std::vector<Vec2>& corners,
                        const trace::Scanline* row, const viz::Typography& type) {
  const cv::Rect& view = g.view();
  const auto shown = [&](const cv::Point2d& p) {
    return view.contains(cv::Point(int(std::lround(p.x)), int(std::lround(p.y))));
  };
  Expected e;
  for (std::size_t v = 0; v < corners.size(); ++v) {
    const cv::Point2d p = g.to_frame(corners[v].x, corners[v].y);
    if (!shown(p)) continue;
    e.marks.push_back({p, double(type.px(7) + type.px(2)), fmt::format("vertex v{}", v)});
    e.wanted.push_back(fmt::format("v{} ", v));
  }
  if (!row) return e;
  for (const trace::ActivePoint& p : row->active_points) {
    const cv::Point2d q = g.to_frame(p.x, double(row->y));
    if (!shown(q)) continue;
    e.marks.push_back({q, double(type.px(6) + type.px(2)), fmt::format("x = {}", p.x)});
    // The label says the trace's x to two decimals.
    e.wanted.push_back(fmt::format("x = {:.2f}", p.x));
  }
  e.wanted.push_back(fmt::format("y = {}", row->y));
  return e;
}

// Every wanted text is a label's (an x to within its two decimals).
void check_labels_shown(const std::vector<const viz::PlacedBox*>& covering,
                        const std::vector<std::string>& wanted) {
  for (const std::string& w : wanted) {
    INFO("label wanted: " << w);
    const bool found = std::any_of(covering.begin(), covering.end(), [&](const auto* p) {
      if (p->kind != viz::PlacedKind::label) return false;
      if (w.rfind("x = ", 0) == 0 && p->text.rfind("x = ", 0) == 0)
        return std::abs(std::stod(p->text.substr(4)) - std::stod(w.substr(4))) < 0.0051;
      return p->text.rfind(w, 0) == 0;
    });
    CHECK(found);
  }
}

// The main view's labels and insets lie inside it, over no mark and no other of them.
void check_nothing_covered(const std::vector<const viz::PlacedBox*>& covering,
                           const std::vector<Disc>& marks, const cv::Rect& view) {
  for (std::size_t k = 0; k < covering.size(); ++k) {
    const viz::PlacedBox& p = *covering[k];
    INFO((p.kind == viz::PlacedKind::inset ? "inset " : "label ") << p.text << " at "
                                                                  << describe(p.box));
    CHECK((p.box & view) == p.box);
    for (const Disc& d : marks) {
      INFO("over " << d.what);
      CHECK_FALSE(overlaps(p.box, d));
    }
    for (std::size_t j = k + 1; j < covering.size(); ++j) {
      INFO("and " << covering[j]->text << " at " << describe(covering[j]->box));
      CHECK((p.box & covering[j]->box).empty());
    }
  }
}

// Inside an inset, its own x labels keep off its points and its title.
void check_inset_layers(const std::vector<viz::PlacedBox>& placed) {
  for (const int layer : {1, 2}) {
    std::vector<const viz::PlacedBox*> in;
    for (const viz::PlacedBox& p : placed)
      if (p.layer == layer) in.push_back(&p);
    for (std::size_t k = 0; k < in.size(); ++k)
      for (std::size_t j = k + 1; j < in.size(); ++j) {
        if (in[k]->kind != viz::PlacedKind::label && in[j]->kind != viz::PlacedKind::label)
          continue;  // two markers may touch: the points of a row meeting at a vertex
        INFO("inset " << layer << ": " << in[k]->text << " " << describe(in[k]->box) << " and "
                      << in[j]->text << " " << describe(in[j]->box));
        CHECK((in[k]->box & in[j]->box).empty());
      }
  }
}

}  // namespace

TEST_CASE("labels and zoom insets cover no marker and no other label", "[viz][placement]") {
  for (const Case& c : cases())
    for (const cv::Size size : {cv::Size(640, 360), cv::Size(1280, 720), cv::Size(1920, 1080)}) {
      const viz::Typography type(size);
      // Every row a step of its own: no row's layout is skipped.
      viz::StepOptions every_row;
      every_row.rows_per_step = 1;
      every_row.max_scanline_steps = 1 << 20;
      viz::Replayer r(c.trace, every_row, size, "test");
      const trace::TriangleBegin& b = c.trace.triangle_begin(0);
      const std::vector<Vec2>& corners = b.snapped.empty() ? b.vertices : b.snapped;
      for (std::size_t i = 0; i < r.steps().size(); ++i) {
        const viz::Step& step = r.steps()[i];
        INFO(c.name << " at " << size.width << "x" << size.height << ", step " << i);
        const std::vector<viz::PlacedBox> placed = placed_from_marks(r.display_list(i));
        const std::optional<viz::ViewGeometry> g = r.geometry(i);
        // Vertices are marked on every frame that shows this one polygon, cards included.
        const bool shows_vertices = g && step.kind != viz::StepKind::painter_batch &&
                                    step.kind != viz::StepKind::scene_done;
        if (!shows_vertices) continue;
        const trace::Scanline* row = step.kind == viz::StepKind::scanlines
                                         ? viz::find_scanline(c.trace, step.triangle, step.last_row)
                                         : nullptr;
        const Expected e = expected_marks(*g, corners, row, type);
        std::vector<const viz::PlacedBox*> covering;  // labels and insets of the main view
        for (const viz::PlacedBox& p : placed)
          if (p.layer == 0 &&
              (p.kind == viz::PlacedKind::label || p.kind == viz::PlacedKind::inset))
            covering.push_back(&p);
        check_labels_shown(covering, e.wanted);
        check_nothing_covered(covering, e.marks, g->view());
        // Cells too small for a grid: the span's ends are shown in insets, which found room.
        if (row && !row->active_points.empty() && g->cell() < viz::GridView::kMinGridCell)
          CHECK(std::count_if(covering.begin(), covering.end(), [](const auto* p) {
                  return p->kind == viz::PlacedKind::inset;
                }) >= 1);
        check_inset_layers(placed);
      }
    }
}
