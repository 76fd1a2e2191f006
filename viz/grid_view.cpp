#include "viz/grid_view.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "src/image.hpp"
#include "viz/palette.hpp"
#include "viz/text_format.hpp"
#include "viz/trace_lookup.hpp"

namespace scantrace::viz {
namespace {

Scalar to_scalar(const Color& c) {
  return {static_cast<double>(to_byte(static_cast<float>(c.b))),
          static_cast<double>(to_byte(static_cast<float>(c.g))),
          static_cast<double>(to_byte(static_cast<float>(c.r)))};
}

bool is_dark(const Vec3b& bgr) {
  return 0.114 * bgr[0] + 0.587 * bgr[1] + 0.299 * bgr[2] < 110;
}

}  // namespace

GridView::GridView(FrameView& frame, const ViewGeometry& geometry, const Typography& type,
                   Size canvas, int layer)
    : frame_(frame),
      geometry_(geometry),
      type_(type),
      canvas_(canvas),
      placement_(geometry.view(), layer) {}

void GridView::label(const std::string& text, TextStyle style, const std::vector<Rect>& candidates,
                     const Scalar& box, std::optional<Scalar> border) {
  const std::optional<Rect> spot = placement_.place(PlacedKind::label, candidates, text);
  if (!spot) return;
  const Point offset = -type_.boxed_area(text, {0, 0}, style, border.has_value()).tl();
  type_.draw_boxed(frame_, text, spot->tl() + offset, style, palette::kText, box, border,
                   mark(MarkKind::label, *spot, text));
}

std::vector<Rect> GridView::around(const std::string& text, TextStyle style, bool bold_border,
                                   Point2d p, int radius, Point2d preferred) const {
  const Size s = type_.boxed_area(text, {0, 0}, style, bold_border).size();
  return boxes_around(p, radius, s, preferred, type_.px(3), s.height / 2);
}

void GridView::cells(const CanvasState& state, std::optional<Color> background) {
  const Rect& v = geometry_.view();
  const std::size_t w = static_cast<std::size_t>(v.width);
  const Scalar bg = background ? to_scalar(*background) : Scalar{};
  const Vec3b empty =
      background ? Vec3b(static_cast<std::uint8_t>(bg[0]), static_cast<std::uint8_t>(bg[1]),
                         static_cast<std::uint8_t>(bg[2]))
                 : Vec3b(palette::kEmptyCell[0], palette::kEmptyCell[1], palette::kEmptyCell[2]);
  const Vec3b outside(palette::kOutsideCanvas[0], palette::kOutsideCanvas[1],
                      palette::kOutsideCanvas[2]);
  // Per column of the view, once: a row of the canvas as it shows unwritten (`blank`: outside
  // the canvas or empty), and the window's column it shows, or -1 (outside the window). Each row
  // is then its blank row copied, and the written pixels of the window put on it, rather than
  // deciding every frame pixel from its canvas coordinates (docs/performance.md, "Ninth round").
  const std::int64_t wx0 = state.window().x, wx1 = wx0 + state.window().width;
  std::vector<Vec3b> blank(w);
  std::vector<int> window_column(w, -1);
  for (std::size_t u = 0; u < w; ++u) {
    const std::int64_t x = geometry_.pixel_x(v.x + static_cast<int>(u));
    const bool on_canvas = x >= 0 && x < canvas_.width;
    blank[u] = on_canvas ? empty : outside;
    if (on_canvas && x >= wx0 && x < wx1) window_column[u] = static_cast<int>(x - wx0);
  }
  auto cells = std::make_shared<std::vector<Vec3b>>(w * static_cast<std::size_t>(v.height));
  std::int64_t previous_y = 0;
  for (int r = 0; r < v.height; ++r) {
    const std::int64_t y = geometry_.pixel_y(v.y + r);
    Vec3b* out = cells->data() + static_cast<std::size_t>(r) * w;
    // A row of the same canvas row as the one above: a copy of it (a cell is many frame rows,
    // and the explorer draws a frame per drag move).
    if (r > 0 && y == previous_y) {
      std::copy(out - v.width, out, out);
      continue;
    }
    previous_y = y;
    if (y < 0 || y >= canvas_.height) {
      std::fill(out, out + v.width, outside);
      continue;
    }
    std::copy(blank.begin(), blank.end(), out);
    // Whole rows of the state at once: a view has hundreds of thousands of frame pixels.
    const Vec3b* pixels = state.row_pixels(y);
    const std::uint8_t* written = state.row_mask(y);
    if (!written) continue;
    for (std::size_t u = 0; u < w; ++u)
      if (const int i = window_column[u]; i >= 0 && written[i]) out[u] = pixels[i];
  }
  cells_ = cells;
  // One block for the view; the backends crop it to the frame, as writing pixels did.
  frame_.pixels(v, std::move(cells), mark(MarkKind::cells, v & Rect({0, 0}, frame_.size()), {}));
}

Vec3b GridView::cell_colour(Point p) const {
  // What cells() put at frame pixel `p` (inside the view): grid() draws the centres on it.
  const Rect& v = geometry_.view();
  return (*cells_)[static_cast<std::size_t>(p.y - v.y) * static_cast<std::size_t>(v.width) +
                   static_cast<std::size_t>(p.x - v.x)];
}

Mark GridView::mark(MarkKind kind, const Rect& box, std::string what) const {
  // Clipped to the view, as the placement keeps its boxes.
  return {kind, std::move(what), (box & placement_.area()) + frame_.area().tl(),
          placement_.layer()};
}

void GridView::grid() {
  if (!grid_visible()) return;
  const Rect& v = geometry_.view();
  const PixelBox b = geometry_.visible();
  // Cell borders, then the centres on top, dark on light cells and light on dark ones.
  for (std::int64_t x = b.x0; x <= b.x1 + 1; ++x) {
    const int u = static_cast<int>(std::lround(at(static_cast<double>(x) - 0.5, 0).x));
    if (u >= v.x && u < v.x + v.width)
      frame_.line({u, v.y}, {u, v.y + v.height - 1}, palette::kGridLine, 1);
  }
  for (std::int64_t y = b.y0; y <= b.y1 + 1; ++y) {
    const int w = static_cast<int>(std::lround(at(0, static_cast<double>(y) - 0.5).y));
    if (w >= v.y && w < v.y + v.height)
      frame_.line({v.x, w}, {v.x + v.width - 1, w}, palette::kGridLine, 1);
  }
  const double cell = geometry_.cell();
  const int radius = cell >= 14 ? std::max(1, static_cast<int>(cell / 14)) : 0;
  for (std::int64_t y = b.y0; y <= b.y1; ++y)
    for (std::int64_t x = b.x0; x <= b.x1; ++x) {
      const Point2d c = at(static_cast<double>(x), static_cast<double>(y));
      const Point p(static_cast<int>(std::lround(c.x)), static_cast<int>(std::lround(c.y)));
      if (!v.contains(p)) continue;
      // Grid lines run between the cells (cells are 6 frame pixels or more here), so the pixel
      // under a centre is its cell's colour.
      const Scalar colour =
          is_dark(cell_colour(p)) ? palette::kCentreOnDark : palette::kCentreOnLight;
      if (radius == 0)
        frame_.pixel(
            p, Vec3b(static_cast<std::uint8_t>(colour[0]), static_cast<std::uint8_t>(colour[1]),
                     static_cast<std::uint8_t>(colour[2])));
      else
        frame_.circle(p, radius, colour, FILLED, LINE_AA);
    }
}

void GridView::outline(std::span<const Vec2> polygon, const Scalar& colour,
                       double design_thickness) {
  const int t = type_.px(design_thickness);
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    draw_segment(frame_, at(a.x, a.y), at(b.x, b.y), geometry_.view(), colour, t);
  }
}

void GridView::outline(const trace::TriangleBegin& polygon, const Scalar& colour,
                       double design_thickness) {
  for (const std::vector<Vec2>& c : contours_of(polygon)) outline(c, colour, design_thickness);
}

void GridView::spans(const trace::Scanline& row) {
  if (row.intervals)
    for (const trace::Interval& iv : *row.intervals) span(row.y, iv.pixels);
  else if (row.span)
    span(row.y, *row.span);
}

void GridView::edge(Vec2 from, Vec2 to, int id, bool active) {
  draw_segment_with_halo(frame_, at(from.x, from.y), at(to.x, to.y), geometry_.view(),
                         palette::edge_colour(id), type_.px(active ? 4 : 2), palette::kHalo,
                         type_.px(1));
}

void GridView::vertices(const trace::TriangleBegin& triangle) {
  vertex_markers(triangle);
  vertex_labels(triangle);
}

namespace {

constexpr double kVertexRadius = 7, kPointRadius = 6, kRing = 2;  // design pixels

const std::vector<Vec2>& corners_of(const trace::TriangleBegin& t) {
  return t.snapped.empty() ? t.vertices : t.snapped;
}

Point rounded(Point2d p) {
  return {static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y))};
}

}  // namespace

void GridView::vertex_markers(const trace::TriangleBegin& triangle) {
  const std::vector<Vec2>& p = corners_of(triangle);
  const int r = type_.px(kVertexRadius), ring = r + type_.px(kRing);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point q = rounded(at(p[i].x, p[i].y));
    if (!geometry_.view().contains(q)) continue;
    const Color col = i < triangle.colors.size() ? triangle.colors[i] : Color{};
    const std::string name = fmt::format("v{}", i);
    frame_.circle(q, ring, palette::kHalo, FILLED, LINE_AA,
                  mark(MarkKind::vertex, marker_box(q, ring), name));
    frame_.circle(q, r, to_scalar(col), FILLED, LINE_AA);
    placement_.mark(PlacedKind::vertex, marker_box(q, ring), name);
  }
}

void GridView::vertex_labels(const trace::TriangleBegin& triangle) {
  const std::vector<Vec2>& p = corners_of(triangle);
  if (p.empty()) return;
  Vec2 centre{0, 0};
  for (const Vec2& v : p) centre = {centre.x + v.x / p.size(), centre.y + v.y / p.size()};
  const Point2d c = at(centre.x, centre.y);
  const int ring = type_.px(kVertexRadius) + type_.px(kRing);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point2d q = at(p[i].x, p[i].y);
    if (!geometry_.view().contains(rounded(q))) continue;
    // Away from the polygon's centre first, so the label does not cover the polygon.
    const Point2d away = q == c ? Point2d(0, -1) : q - c;
    const std::string text = fmt::format("v{} {}", i, point(p[i]));
    label(text, TextStyle::body, around(text, TextStyle::body, false, q, ring, away),
          palette::kLabelBox);
  }
}

void GridView::scanline(std::int64_t y) {
  const Rect& v = geometry_.view();
  const double w = at(0, static_cast<double>(y)).y;
  const int half = type_.px(2) / 2 + type_.px(1) + 1;
  draw_segment_with_halo(
      frame_, {static_cast<double>(v.x), w}, {static_cast<double>(v.x + v.width), w}, v,
      palette::kScanline, type_.px(2), palette::kHalo, type_.px(1),
      mark(MarkKind::scanline,
           Rect(v.x, static_cast<int>(std::floor(w)) - half, v.width, 2 * half + 1) & v,
           fmt::format("y = {}", y)));
}

void GridView::scanline_label(std::int64_t y) {
  const Rect& v = geometry_.view();
  const double w = at(0, static_cast<double>(y)).y;
  const std::string text = fmt::format("y = {}", y);
  const Size s = type_.boxed_area(text, {0, 0}, TextStyle::strong).size();
  // On the row at the view's left edge, where the eye looks for it; then the right edge, then
  // above and below the row, then along it.
  const int m = type_.px(4);
  const std::vector<int> xs{v.x + m, v.x + v.width - m - s.width, v.x + v.width / 4 - s.width / 2,
                            v.x + v.width / 2 - s.width / 2, v.x + 3 * v.width / 4 - s.width / 2};
  std::vector<Rect> candidates;
  for (const int dy : {0, -1, 1, -2, 2, -3, 3})
    for (std::size_t i = 0; i < xs.size(); ++i)
      if (i < 2 || dy == 0 || std::abs(dy) == 3)
        candidates.emplace_back(xs[i], static_cast<int>(w) - s.height / 2 + dy * s.height, s.width,
                                s.height);
  label(text, TextStyle::strong, candidates, palette::kScanline);
}

void GridView::span(std::int64_t y, const trace::Span& span) {
  if (span.size() <= 0) return;
  const Point2d a = at(static_cast<double>(span.x_begin) - 0.5, static_cast<double>(y) - 0.5);
  const Point2d b = at(static_cast<double>(span.x_end) - 0.5, static_cast<double>(y) + 0.5);
  // The box is drawn just outside the span's cells, so it frames their colours without covering
  // them; small cells get a box tall enough to be seen, centred on the row.
  const int thickness = type_.px(2), halo = type_.px(1);
  const double out = thickness / 2.0 + halo;
  const double min_height = type_.px(10);
  const double mid = (a.y + b.y) / 2, half = std::max((b.y - a.y) / 2 + out, min_height / 2);
  const Point2d tl(a.x - out, mid - half), br(b.x + out, mid + half);
  const Point2d tr(br.x, tl.y), bl(tl.x, br.y);
  // The box's mark rides on its first side: the area inside the halo's outer edge.
  const double edge = thickness / 2.0 + halo;
  std::optional<Mark> box = mark(MarkKind::span,
                                 Rect(Point(static_cast<int>(std::floor(tl.x - edge)),
                                            static_cast<int>(std::floor(tl.y - edge))),
                                      Point(static_cast<int>(std::ceil(br.x + edge)) + 1,
                                            static_cast<int>(std::ceil(br.y + edge)) + 1)) &
                                     geometry_.view(),
                                 fmt::format("[{}, {})", span.x_begin, span.x_end));
  for (auto [p, q] : {std::pair{tl, tr}, std::pair{tr, br}, std::pair{br, bl}, std::pair{bl, tl}}) {
    draw_segment_with_halo(frame_, p, q, geometry_.view(), palette::kSpan, thickness,
                           palette::kHalo, halo, std::move(box));
    box.reset();
  }
}

void GridView::active_points(const trace::Scanline& row) {
  active_point_markers(row);
  active_point_labels(row);
}

void GridView::active_point_markers(const trace::Scanline& row) {
  const int r = type_.px(kPointRadius), ring = r + type_.px(kRing);
  for (const trace::ActivePoint& p : row.active_points) {
    const Point q = rounded(at(p.x, static_cast<double>(row.y)));
    if (!geometry_.view().contains(q)) continue;
    const std::string name = fmt::format("e{}", p.edge);
    frame_.circle(q, ring, palette::edge_colour(p.edge), FILLED, LINE_AA,
                  mark(MarkKind::active_point, marker_box(q, ring), name));
    frame_.circle(q, r, to_scalar(p.color), FILLED, LINE_AA);
    placement_.mark(PlacedKind::active_point, marker_box(q, ring), name);
  }
}

void GridView::active_point_labels(const trace::Scanline& row) {
  const std::size_t n = row.active_points.size();
  const int ring = type_.px(kPointRadius) + type_.px(kRing);
  for (std::size_t i = 0; i < n; ++i) {
    const trace::ActivePoint& p = row.active_points[i];
    const Point2d q = at(p.x, static_cast<double>(row.y));
    if (!geometry_.view().contains(rounded(q))) continue;
    // The leftmost label goes left of its point, the rightmost right of it, so the two x values
    // of a row read apart even where the points meet at a vertex. With more points (general
    // polygons) the ones between alternate above and below the row.
    Point2d preferred(0, -1);
    if (n >= 2 && i == 0) preferred = {-1, -1};
    if (n >= 2 && i == n - 1) preferred = {1, -1};
    if (n > 2 && i > 0 && i + 1 < n && i % 2 == 1) preferred = {0, 1};
    const std::string text = fmt::format("x = {}", display_number(p.x, 2));
    label(text, TextStyle::strong, around(text, TextStyle::strong, true, q, ring, preferred),
          palette::kLabelBox, palette::edge_colour(p.edge));
  }
}

}  // namespace scantrace::viz
