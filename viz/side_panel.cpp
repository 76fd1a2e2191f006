#include "viz/side_panel.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "viz/palette.hpp"
#include "viz/panel_writer.hpp"
#include "viz/text_format.hpp"
#include "viz/trace_lookup.hpp"

namespace scantrace::viz {
namespace {

using trace::EdgeEntry;
using trace::EdgeTableEvent;
using trace::Scanline;
using trace::TriangleBegin;

bool top_left_rule(const trace::Trace& t) {
  return t.header().fill_rule != FillRule::closed;
}

std::string rows_text(const EdgeEntry& e) {
  if (e.first_row > e.last_row) return "none";
  return fmt::format("{}..{}", e.first_row, e.last_row);
}

std::string id_list(const std::vector<int>& ids) {
  std::string s;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    s += i == 0 ? "e" : (i + 1 == ids.size() ? " and e" : ", e");
    s += std::to_string(ids[i]);
  }
  return s;
}

// The edge table; `listed` entries shown (all when negative), entry `newest` highlighted, and
// with a current row, the edges not active on it greyed out.
void edge_table(PanelWriter& w, const EdgeTableEvent& table, const TriangleBegin* b, int listed,
                int newest, const Scanline* row) {
  std::vector<TableRow> rows;
  const int n = static_cast<int>(table.edges.size());
  for (int i = 0; i < n && (listed < 0 || i < listed); ++i) {
    const EdgeEntry& e = table.edges[i];
    TableRow r;
    r.cells = {edge_name(e.edge, b),         display_number(e.y_min),    display_number(e.y_max),
               display_number(e.x_at_y_min), display_number(e.dx_dy, 4), rows_text(e)};
    r.marker = palette::edge_colour(e.edge);
    r.highlighted = i == newest;
    if (row)
      r.muted = std::none_of(row->active_edges.begin(), row->active_edges.end(),
                             [&](const trace::EdgeCrossing& a) { return a.edge == e.edge; });
    rows.push_back(r);
  }
  w.table({{"edge", false}, {"y_min"}, {"y_max"}, {"x at y_min"}, {"dx/dy"}, {"active rows"}},
          rows);
}

void setup_panel(PanelWriter& w, const trace::Trace& t, const TriangleBegin& b) {
  const trace::Header& h = t.header();
  w.heading("1  Set-up: vertices and colours");
  const bool snapped_differ = !b.snapped.empty() && b.snapped != b.vertices;
  w.paragraph(fmt::format(
      "Coverage is decided on the vertices snapped to a 1/{}-pixel grid, in exact integer "
      "arithmetic {}",
      1 << std::clamp(h.subpixel_bits, 0, 30),
      snapped_differ ? "(the snapped positions differ from the given ones here)."
                     : "(these vertices are already on it)."));
  w.gap(6);
  std::vector<TableRow> rows;
  for (std::size_t i = 0; i < b.vertices.size(); ++i) {
    TableRow r;
    const Vec2 s = i < b.snapped.size() ? b.snapped[i] : b.vertices[i];
    r.cells = {fmt::format("v{}", i), point(b.vertices[i], 3), point(s, 4)};
    rows.push_back(r);
  }
  w.table({{"vertex", false}, {"given (x, y)"}, {"snapped (x, y)"}}, rows);
  w.gap(8);
  for (std::size_t i = 0; i < b.colors.size(); ++i)
    w.swatch(b.colors[i], fmt::format("v{} colour (r, g, b) = {}", i, colour(b.colors[i])));
  if (b.depth)
    w.line(fmt::format("depth {} (mean of the vertex depths)", display_number(*b.depth, 4)));
  w.gap(8);
  if (b.flat_color) {
    w.paragraph("Flat shading: every pixel gets one colour, the mean of the vertex colours:");
    w.swatch(*b.flat_color, fmt::format("(c0 + c1 + c2) / 3 = {}", colour(*b.flat_color)));
  } else {
    w.paragraph(
        "Gouraud shading: vertex colours are interpolated linearly, first along the two active "
        "edges (per row), then along the row between them (per pixel).");
  }
  w.gap(8);
  if (t.header().winding_rule)
    w.paragraph(fmt::format(
        "Winding rule {}: on each row every active edge counts +1 (going down) or -1 (going "
        "up); a pixel centre is inside when the edges at or left of it {}. Contours after the "
        "first are holes or more pieces, as the rule decides.",
        to_string(*t.header().winding_rule),
        *t.header().winding_rule == WindingRule::non_zero ? "sum to a non-zero winding number"
                                                          : "are odd in number"));
  else if (top_left_rule(t))
    w.paragraph(
        "Fill rule top-left: a pixel is filled when its centre lies inside the triangle, or on "
        "a top or left edge. So rows ceil(y_min)~..~ceil(y_max)~-~1 are filled, and on each "
        "row the columns ceil(x_L)~..~ceil(x_R)~-~1.");
  else
    w.paragraph(
        "Fill rule closed: every pixel centre inside or on the boundary is filled (both ends "
        "inclusive) - so pixels on an edge shared with a neighbour are painted twice.");
  w.gap(8);
  w.paragraph("Next: the edge table.", TextStyle::body, palette::kMutedText);
}

void entry_panel(PanelWriter& w, const trace::Trace& t, const TriangleBegin* b,
                 const EdgeTableEvent& table, int entry) {
  const int n = static_cast<int>(table.edges.size());
  w.heading("2  Building the edge table");
  w.paragraph(
      "One entry per edge that crosses scanlines: where it starts (y_min and x there), where it "
      "ends (y_max), and dx/dy, how far x moves from one row to the next. Sorted by y_min.");
  w.gap(6);
  edge_table(w, table, b, std::min(entry + 1, n), entry < n ? entry : -1, nullptr);
  w.gap(10);
  if (entry < n) {
    const EdgeEntry& e = table.edges[entry];
    const int to = next_vertex(b, e.edge);
    // Entries run top to bottom: `from` is stored in the edge's own direction, so name the
    // endpoints by y rather than by vertex.
    const Vec2 top = e.from.y <= e.to.y ? e.from : e.to,
               bottom = e.from.y <= e.to.y ? e.to : e.from;
    w.line(fmt::format("New entry: e{}, from v{} to v{}", e.edge, e.edge, to), TextStyle::strong);
    w.gap(6);
    const bool tl = top_left_rule(t);
    w.formula({"dx/dy = (x_bottom - x_top) / (y_bottom - y_top)",
               fmt::format("      = ({} - {}) / ({} - {}) = {}", display_number(bottom.x),
                           display_number(top.x), display_number(bottom.y), display_number(top.y),
                           display_number(e.dx_dy, 4)),
               fmt::format("active rows: {} = {}",
                           tl ? "ceil(y_min) .. ceil(y_max) - 1" : "ceil(y_min) .. floor(y_max)",
                           rows_text(e))});
  } else {
    const trace::HorizontalEntry& hz = table.horizontal[entry - n];
    w.line(fmt::format("e{} is horizontal (y = {}): no entry", hz.edge, display_number(hz.y)),
           TextStyle::strong);
    std::string reason = hz.reason;
    if (!reason.empty()) reason[0] = static_cast<char>(std::toupper(reason[0]));
    w.paragraph(reason + ".");
  }
  w.gap(12);
  w.paragraph(
      "Then the scanlines, top to bottom: an edge joins the active edge table on its first "
      "row and leaves it after its last; x of an active edge on the next row is x~+~dx/dy.",
      TextStyle::body, palette::kMutedText);
}

std::string narrative(const trace::Trace& t, const Step& step, const Scanline& row,
                      const EdgeTableEvent* table) {
  std::string s;
  if (step.first_row != step.last_row)
    s = fmt::format(
        "Rows {} .. {}: on each row every active edge moves by its dx/dy, and the pixels "
        "between the active points are filled. ",
        step.first_row, step.last_row);
  if (!row.entered.empty()) {
    const bool many = row.entered.size() > 1;
    s +=
        fmt::format("{} {} the active edge table: row {} is the first row {}", id_list(row.entered),
                    many ? "enter" : "enters", row.y, many ? "they cross" : "it crosses");
    if (const EdgeEntry* e = find_edge(table, row.entered.front()))
      s += fmt::format(" (y_min = {})", display_number(e->y_min));
    s += ". ";
  }
  if (!row.retired.empty()) {
    const bool many = row.retired.size() > 1;
    s += fmt::format("{} {} it: row {} was {} last", id_list(row.retired),
                     many ? "leave" : "leaves", row.y - 1, many ? "their" : "its");
    if (const EdgeEntry* e = find_edge(table, row.retired.front()))
      s += fmt::format(" (y_max = {})", display_number(e->y_max));
    s += ". ";
  }
  if (!row.span && row.active_points.size() >= 2)
    s += "No pixel centre lies between the active points: nothing is filled on this row. ";
  if (s.empty())
    s = "x of each active edge = its x on the previous row + dx/dy. The pixels between the "
        "active points are filled. ";
  (void)t;
  return s;
}

// A row of a general polygon (docs/polygons.md): any even number of active edges, each with its
// winding direction and the running winding number after it, and the inside intervals.
void polygon_scanline_panel(PanelWriter& w, const trace::Trace& t, const Step& step,
                            const TriangleBegin* b, const EdgeTableEvent* table,
                            const Scanline& row) {
  const std::string rule = to_string(t.header().winding_rule.value_or(WindingRule::even_odd));
  const bool even_odd = t.header().winding_rule != WindingRule::non_zero;
  w.heading(step.first_row == step.last_row
                ? fmt::format("3  Scanline y = {}", row.y)
                : fmt::format("3  Scanlines y = {} .. {}", step.first_row, step.last_row));
  w.paragraph(fmt::format(
      "Walking the row left to right, each active edge adds its winding (+1 going down, -1 going "
      "up). Rule {}: a pixel is inside where {}. Inside intervals fill ceil(x_L)~..~ceil(x_R)~-~1.",
      rule, even_odd ? "the count of edges passed is odd" : "the winding sum is not zero"));
  w.gap(6);
  w.line(fmt::format("Active edge table at y = {} ({} edges)", row.y, row.active_edges.size()),
         TextStyle::strong);
  std::vector<TableRow> aet;
  int winding = 0;
  for (const trace::EdgeCrossing& a : row.active_edges) {
    const EdgeEntry* e = find_edge(table, a.edge);
    const int d = a.winding.value_or(0);
    winding += d;
    const bool inside = even_odd ? (winding & 1) != 0 : winding != 0;
    TableRow r;
    r.cells = {edge_name(a.edge, b), fixed(a.x, 3), d > 0 ? "+1 down" : "-1 up",
               fmt::format("{}{}", winding, inside ? "  in" : "  out"),
               e ? display_number(e->y_max) : "?"};
    r.marker = palette::edge_colour(a.edge);
    aet.push_back(r);
  }
  w.table({{"edge", false}, {"x on this row"}, {"winding"}, {"sum after"}, {"y_max"}}, aet);
  w.gap(8);
  if (!row.intervals || row.intervals->empty()) {
    w.line("Inside intervals: none with a pixel centre on this row", TextStyle::body);
    return;
  }
  w.line(fmt::format("Inside intervals ({})", row.intervals->size()), TextStyle::strong);
  const std::optional<Color> flat = b ? b->flat_color : std::nullopt;
  // Swatches for up to two intervals; more would push the formula off the panel.
  const bool swatches = row.intervals->size() <= 2;
  for (const trace::Interval& iv : *row.intervals) {
    w.line(fmt::format("e{} .. e{}: x = {} .. {}  -> pixels {} .. {}", iv.left_edge, iv.right_edge,
                       fixed(iv.x_left, 2), fixed(iv.x_right, 2), iv.pixels.x_begin,
                       iv.pixels.x_end - 1),
           TextStyle::body);
    if (!swatches) continue;
    if (iv.colors) {
      w.swatch(iv.colors->begin,
               fmt::format("pixel {}: {}", iv.pixels.x_begin, colour(iv.colors->begin)));
      if (iv.pixels.size() > 1)
        w.swatch(iv.colors->end,
                 fmt::format("pixel {}: {}", iv.pixels.x_end - 1, colour(iv.colors->end)));
    } else if (flat) {
      w.swatch(*flat, fmt::format("flat colour {}", colour(*flat)));
    }
  }
  w.gap(8);
  w.formula({"per row:    x += dx/dy for each active edge; re-sort by x",
             "per pixel:  c(x) = c_L + (x - x_L) / (x_R - x_L) * (c_R - c_L)"});
}

// The active edge table of the row: each edge's x on it, dx/dy and y_max.
void active_edge_table(PanelWriter& w, const EdgeTableEvent* table, const TriangleBegin* b,
                       const Scanline& row) {
  w.line(fmt::format("Active edge table at y = {}", row.y), TextStyle::strong);
  std::vector<TableRow> aet;
  for (const trace::EdgeCrossing& a : row.active_edges) {
    TableRow r;
    const EdgeEntry* e = find_edge(table, a.edge);
    r.cells = {edge_name(a.edge, b), fixed(a.x, 3), e ? display_number(e->dx_dy, 4) : "?",
               e ? display_number(e->y_max) : "?"};
    r.marker = palette::edge_colour(a.edge);
    aet.push_back(r);
  }
  w.table({{"edge", false}, {"x on this row"}, {"dx/dy"}, {"y_max"}}, aet);
}

// The row's active points with their colours, and its span: its pixels, the rule that bounds
// them and the colours of its end pixels.
void span_lines(PanelWriter& w, const trace::Trace& t, const TriangleBegin* b,
                const Scanline& row) {
  const std::size_t np = row.active_points.size();
  for (std::size_t i = 0; i < np; ++i) {
    const trace::ActivePoint& p = row.active_points[i];
    const std::string name = np == 2 ? (i == 0 ? "x_L" : "x_R") : fmt::format("x{}", i);
    w.swatch(p.color,
             fmt::format("{} = {} (e{})   c = {}", name, fixed(p.x, 3), p.edge, colour(p.color)));
  }
  if (!row.span || row.span->size() <= 0) {
    w.line("Span: empty", TextStyle::body);
    return;
  }
  const trace::Span& s = *row.span;
  // The rule's bounds, unless the canvas edge cut the span (the trace holds the clipped one).
  const double xl = row.active_points.front().x, xr = row.active_points.back().x;
  const int width = t.header().canvas.width;
  const bool clipped = (s.x_begin == 0 && xl < -1) || (s.x_end == width && xr > width + 1);
  w.line(fmt::format("Span: x = {} .. {}  ({} {}) = {}", s.x_begin, s.x_end - 1,
                     integer(s.size()), s.size() == 1 ? "pixel" : "pixels",
                     clipped            ? "clipped to the canvas"
                     : top_left_rule(t) ? "ceil(x_L) .. ceil(x_R) - 1"
                                        : "ceil(x_L) .. floor(x_R)"),
         TextStyle::body);
  std::optional<Color> flat = b ? b->flat_color : std::nullopt;
  if (row.span_colors) {
    w.swatch(row.span_colors->begin,
             fmt::format("pixel {}: {}", s.x_begin, colour(row.span_colors->begin)));
    if (s.size() > 1)
      w.swatch(row.span_colors->end,
               fmt::format("pixel {}: {}", s.x_end - 1, colour(row.span_colors->end)));
  } else if (flat) {
    w.swatch(*flat, fmt::format("every pixel: the flat colour {}", colour(*flat)));
  }
}

// The per-row and per-pixel formulas, each with a worked instance from this row's numbers.
std::vector<std::string> scanline_formulas(const trace::Trace& t, const Step& step,
                                           const TriangleBegin* b, const EdgeTableEvent* table,
                                           const Scanline& row) {
  std::vector<std::string> f{"per row:    x += dx/dy  for each active edge"};
  // A worked instance with this row's numbers: the previous row's x plus dx/dy.
  if (!row.active_edges.empty())
    if (const Scanline* prev = find_scanline(t, step.triangle, row.y - 1)) {
      const trace::EdgeCrossing& a = row.active_edges.front();
      const EdgeEntry* e = find_edge(table, a.edge);
      for (const trace::EdgeCrossing& p : prev->active_edges)
        if (e && p.edge == a.edge)
          f.push_back(fmt::format("      e{}: {} {} = {}", a.edge, fixed(p.x, 3),
                                  plus_term(e->dx_dy, 4), fixed(a.x, 3)));
    }
  if (b && b->flat_color) {
    f.push_back("per pixel:  c = flat colour = (c0 + c1 + c2) / 3");
    return f;
  }
  f.push_back("per pixel:  c(x) = c_L + t * (c_R - c_L)");
  f.push_back("      t = (x - x_L) / (x_R - x_L)");
  if (row.span && row.span->size() > 0 && row.active_points.size() >= 2) {
    const double xl = row.active_points.front().x, xr = row.active_points.back().x;
    const double t0 = xr > xl ? (static_cast<double>(row.span->x_begin) - xl) / (xr - xl) : 0;
    f.push_back(fmt::format("      t({}) = ({} {}) / ({} {}) = {}", row.span->x_begin,
                            row.span->x_begin, minus_term(xl, 2), display_number(xr, 2),
                            minus_term(xl, 2), fixed(t0, 4)));
  }
  f.push_back("c_L, c_R: interpolated the same way along their edges, in y");
  return f;
}

void scanline_panel(PanelWriter& w, const trace::Trace& t, const Step& step, const TriangleBegin* b,
                    const EdgeTableEvent* table, const Scanline& row) {
  if (row.intervals) return polygon_scanline_panel(w, t, step, b, table, row);
  w.heading(step.first_row == step.last_row
                ? fmt::format("3  Scanline y = {}", row.y)
                : fmt::format("3  Scanlines y = {} .. {}", step.first_row, step.last_row));
  w.paragraph(narrative(t, step, row, table));
  w.gap(6);
  if (table) {
    w.line("Edge table", TextStyle::strong);
    edge_table(w, *table, b, -1, -1, &row);
    w.gap(6);
  }
  active_edge_table(w, table, b, row);
  w.gap(8);
  span_lines(w, t, b, row);
  w.gap(10);
  w.formula(scanline_formulas(t, step, b, table, row));
}

void done_panel(PanelWriter& w, const trace::Trace& t, const TriangleBegin* b,
                const EdgeTableEvent* table, int triangle) {
  w.heading(fmt::format("4  {} {} is filled", t.header().winding_rule ? "Polygon" : "Triangle",
                        triangle));
  if (const auto end = t.triangle_end(triangle))
    w.paragraph(fmt::format("{} {}, {} {} written, each exactly once.", integer(end->rows),
                            end->rows == 1 ? "row" : "rows", integer(end->pixels),
                            end->pixels == 1 ? "pixel" : "pixels"));
  const auto rows = t.scanlines(triangle);
  if (rows.empty())
    w.paragraph(
        "This trace holds no scanlines of it (level triangle): the pixels are not in the "
        "trace, only the set-up and the edge table.",
        TextStyle::body, palette::kMutedText);
  w.gap(6);
  if (table) {
    w.line("Edge table", TextStyle::strong);
    edge_table(w, *table, b, -1, -1, nullptr);
    w.gap(8);
  }
  if (top_left_rule(t))
    w.paragraph(
        "Top-left rule: rows ceil(y_min)~..~ceil(y_max)~-~1 and, per row, columns "
        "ceil(x_L)~..~ceil(x_R)~-~1. A pixel centre exactly on an edge shared by two triangles "
        "belongs to exactly one of them: no gaps, no double painting.");
  else
    w.paragraph(
        "Closed rule: centres on the boundary are filled too, so a neighbour sharing an edge "
        "paints those pixels again.");
  w.gap(8);
  w.formula({"for each row y (edge table -> active edge table):",
             "   add the edges starting at y, drop those that ended",
             "   fill ceil(x_L) .. ceil(x_R) - 1, colour interpolated",
             "   x += dx/dy for every active edge"});
}

}  // namespace

std::string explain_skip(const std::string& reason) {
  if (reason == "degenerate")
    return "Its snapped vertices are collinear: zero area, no interior, so no pixel.";
  if (reason == "no_pixel_centre")
    return "Its bounding box holds no pixel centre: it is too small to own a pixel.";
  if (reason == "offscreen") return "It lies entirely outside the canvas.";
  if (reason == "out_of_range")
    return "A coordinate is not a finite number, or beyond the range the fill handles.";
  if (reason == "too_few_vertices") return "It has fewer than three vertices.";
  return fmt::format("Reason: {}.", reason);
}

int draw_triangle_panel(FrameView& frame, const Rect& area, const Typography& type,
                        const trace::Trace& trace, const Step& step) {
  PanelWriter w(frame, area, type);
  const TriangleBegin* b = find_begin(trace, step.triangle);
  const EdgeTableEvent* table = find_edge_table(trace, step.triangle);
  switch (step.kind) {
    case StepKind::triangle_setup:
      if (b) setup_panel(w, trace, *b);
      break;
    case StepKind::edge_table_entry:
      if (table) entry_panel(w, trace, b, *table, step.entry);
      break;
    case StepKind::scanlines:
      if (const Scanline* row = find_scanline(trace, step.triangle, step.last_row))
        scanline_panel(w, trace, step, b, table, *row);
      break;
    case StepKind::triangle_done:
      done_panel(w, trace, b, table, step.triangle);
      break;
    case StepKind::triangle_skipped: {
      const auto skipped = trace.skipped(step.triangle);
      w.heading(fmt::format("Triangle {} is skipped", step.triangle));
      w.paragraph(explain_skip(skipped ? skipped->reason : ""));
      w.gap(6);
      w.paragraph("The fill checks this before building an edge table, so it costs nothing.",
                  TextStyle::body, palette::kMutedText);
      break;
    }
    default:
      break;
  }
  return w.y();
}

}  // namespace scantrace::viz
