#include "trace_check.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <type_traits>
#include <unordered_map>

#include "reference/exact_reference.hpp"
#include "src/fixed_point.hpp"
#include "trace.hpp"

namespace scantrace::trace {
namespace {

using i128 = reference::i128;

// Gouraud colours are interpolated in double: a blend of components in [0, 1] can land an ulp
// outside. A real excursion (an edited file, a broken writer) is far larger than this.
constexpr double kColorSlack = 1e-9;

i128 floor_div(i128 a, i128 b) {  // b > 0
  const i128 q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

std::string str(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// Built by appending: GCC 12 raises a false -Wrestrict alarm on "literal" + std::string&&.
std::string str(const Color& c) {
  std::string s = "[";
  s += str(c.r) + ", " + str(c.g) + ", " + str(c.b) + "]";
  return s;
}

std::string ids(const std::vector<int>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v[i]);
  return s + "]";
}

struct GridPoint {
  i64 x = 0, y = 0;
};

// Where an edge (grid units, top to bottom) crosses the centre line of row y: x = q + r/den
// exactly, shown as a double the way the fill shows it (q + r/den in double).
struct Crossing {
  i64 q = 0, r = 0, den = 1;
  i64 ceil() const { return q + (r != 0); }
  i64 floor() const { return q; }
  double x() const {
    return static_cast<double>(q) + static_cast<double>(r) / static_cast<double>(den);
  }
};

Crossing crossing(GridPoint top, GridPoint bottom, i64 y, i64 scale) {
  const i128 dy = bottom.y - top.y, dx = bottom.x - top.x;
  const i128 num = static_cast<i128>(top.x) * dy + dx * (static_cast<i128>(y) * scale - top.y);
  const i128 den = static_cast<i128>(scale) * dy;
  const i128 q = floor_div(num, den);
  return {static_cast<i64>(q), static_cast<i64>(num - q * den), static_cast<i64>(den)};
}

struct TriangleState {
  bool ended = false;
  std::size_t vertex_count = 0;
  bool has_table = false;
  std::vector<EdgeEntry> edges;  // of the edge table, as listed
  i64 y_first = 0, y_last = -1;  // rows the sweep visits: the table's rows clipped to the canvas
  std::optional<i64> last_y;
  i64 scanlines = 0, span_pixels = 0, pixel_events = 0;
  // Pixel level: the pixels of a row come before its scanline event.
  std::optional<i64> pending_y;
  std::vector<i64> pending_x;
  // Thorough: the snapped vertices on the grid, and each vertex's successor on its contour.
  std::vector<GridPoint> grid;
  std::vector<int> next;
};

class Checker {
 public:
  Checker(const std::vector<Event>& events, const std::string& name, CheckDepth depth,
          const std::optional<RowRange>& pixel_columns)
      : events_(events),
        name_(name),
        thorough_(depth == CheckDepth::thorough),
        columns_(pixel_columns) {}

  CheckSummary run() {
    const Header& h = std::get<Header>(events_.front());
    line_ = 1;
    check_header(h);
    for (std::size_t i = 1; i < events_.size(); ++i) {
      line_ = i + 1;
      std::visit([&](const auto& e) { check(e); }, events_[i]);
    }
    summary_.events = static_cast<std::int64_t>(events_.size());
    return summary_;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw TraceError(name_ + ":" + std::to_string(line_) + ": " + what);
  }

  // A message, or a callable that makes it: the per-row checks pass callables, so the strings
  // are built only for a failure (building them for every row was most of the check's time, and
  // a third of recording a triangle's trace: the explorer records one on every mouse move).
  static std::string text(const std::string& what) { return what; }
  template <class Make>
    requires std::is_invocable_r_v<std::string, Make>
  static std::string text(const Make& what) {
    return what();
  }

  template <class What>
  void finite(double v, const What& what) const {
    if (!std::isfinite(v)) fail(text(what) + " is not finite (" + str(v) + ")");
  }
  // A begun triangle's vertices are within the fill's range: beyond it the fill skips the
  // triangle (out_of_range) instead of beginning it, and the thorough check's exact snap would
  // overflow its integers.
  template <class What>
  void coordinate(double v, const What& what) const {
    finite(v, what);
    if (std::fabs(v) > kMaxCoordinate)
      fail(text(what) + " " + str(v) +
           " is beyond the fill's range of ±2^30 pixels (the fill skips such a triangle)");
  }
  template <class What>
  void color(const Color& c, const What& what) const {
    for (double v : {c.r, c.g, c.b})
      if (!std::isfinite(v) || v < -kColorSlack || v > 1 + kColorSlack)
        fail(text(what) + " " + str(c) + " is not a colour in [0, 1]");
  }

  void check_header(const Header& h) {
    width_ = h.canvas.width, height_ = h.canvas.height;
    level_ = h.level;  // the reader takes only a known shading, fill rule and level
    if (h.subpixel_bits < 0 || h.subpixel_bits > kMaxSubpixelBits)
      fail("header: subpixel_bits " + std::to_string(h.subpixel_bits) + " is not in 0…" +
           std::to_string(kMaxSubpixelBits));
    closed_ = h.fill_rule == FillRule::closed;
    bits_ = h.subpixel_bits;
    scale_ = i64{1} << bits_;
  }

  // The triangle an event speaks of must have been begun and not yet ended.
  TriangleState& open(int t, const char* what) {
    auto it = state_.find(t);
    if (it == state_.end())
      fail(std::string(what) + " of triangle " + std::to_string(t) +
           ", which was never begun (no triangle_begin before it)");
    if (it->second.ended)
      fail(std::string(what) + " of triangle " + std::to_string(t) + " after its triangle_end");
    return it->second;
  }

  void check(const Header&) { fail("a second header"); }

  void check(const TriangleBegin& b) {
    if (state_.count(b.triangle))
      fail("triangle " + std::to_string(b.triangle) + " is begun a second time");
    const std::string tri = "triangle " + std::to_string(b.triangle);
    const std::size_t n = b.vertices.size();
    if (n < 3) fail(tri + ": " + std::to_string(n) + " vertices (a polygon has at least 3)");
    if (b.snapped.size() != n || b.colors.size() != n)
      fail(tri + ": " + std::to_string(n) + " vertices but " + std::to_string(b.snapped.size()) +
           " snapped vertices and " + std::to_string(b.colors.size()) + " colours");
    for (std::size_t i = 0; i < n; ++i) {
      const std::string v = tri + ": vertex " + std::to_string(i);
      coordinate(b.vertices[i].x, v + " x"), coordinate(b.vertices[i].y, v + " y");
      coordinate(b.snapped[i].x, v + " snapped x"), coordinate(b.snapped[i].y, v + " snapped y");
      color(b.colors[i], v + ": colour");
    }
    if (b.flat_color) color(*b.flat_color, tri + ": flat_color");
    if (b.depth) finite(*b.depth, tri + ": depth");
    TriangleState s;
    s.vertex_count = n;
    // Contours: each vertex exactly once, in order (the writer numbers them 0, 1, 2, …).
    s.next.resize(n);
    if (b.contours.empty()) {
      for (std::size_t i = 0; i < n; ++i) s.next[i] = static_cast<int>((i + 1) % n);
    } else {
      int expected = 0;
      for (const auto& c : b.contours) {
        if (c.size() < 2) fail(tri + ": a contour of " + std::to_string(c.size()) + " vertices");
        for (std::size_t k = 0; k < c.size(); ++k) {
          if (c[k] != expected)
            fail(tri + ": contours list vertex " + std::to_string(c[k]) + " where vertex " +
                 std::to_string(expected) + " comes next");
          ++expected;
          s.next[c[k]] = c[(k + 1) % c.size()];
        }
      }
      if (expected != static_cast<int>(n))
        fail(tri + ": the contours hold " + std::to_string(expected) + " of the " +
             std::to_string(n) + " vertices");
    }
    if (thorough_) {
      for (std::size_t i = 0; i < n; ++i) {
        const std::string v = tri + ": vertex " + std::to_string(i);
        const reference::GridPt g = reference::snap(b.vertices[i], bits_);
        const double sx = static_cast<double>(g.x) / static_cast<double>(scale_);
        const double sy = static_cast<double>(g.y) / static_cast<double>(scale_);
        if (sx != b.snapped[i].x || sy != b.snapped[i].y)
          fail(v + ": snapped [" + str(b.snapped[i].x) + ", " + str(b.snapped[i].y) +
               "] is not the vertex on the 1/" + std::to_string(scale_) + " grid, which is [" +
               str(sx) + ", " + str(sy) + "]");
        s.grid.push_back({g.x, g.y});
      }
    }
    state_.emplace(b.triangle, std::move(s));
    ++summary_.triangles;
  }

  void check(const EdgeTableEvent& t) {
    TriangleState& s = open(t.triangle, "edge table");
    const std::string tri = "edge table of triangle " + std::to_string(t.triangle);
    if (s.has_table) fail("a second " + tri);
    if (s.last_y) fail(tri + " after its scanlines");
    s.has_table = true;
    std::vector<bool> seen(s.vertex_count, false);
    auto id = [&](int e, const char* kind) {
      if (e < 0 || static_cast<std::size_t>(e) >= s.vertex_count)
        fail(tri + ": " + kind + " edge " + std::to_string(e) + " does not exist (" +
             std::to_string(s.vertex_count) + " vertices)");
      if (seen[e]) fail(tri + ": edge " + std::to_string(e) + " is listed twice");
      seen[e] = true;
    };
    i64 first = 0, last = -1;
    bool any = false;
    for (std::size_t k = 0; k < t.edges.size(); ++k) {
      const EdgeEntry& e = t.edges[k];
      id(e.edge, "");
      const std::string en = tri + ": edge " + std::to_string(e.edge);
      for (double v : {e.from.x, e.from.y, e.to.x, e.to.y, e.y_min, e.y_max, e.x_at_y_min, e.dx_dy})
        finite(v, en + ": a value");
      if (!(e.y_min < e.y_max))
        fail(en + ": y_min " + str(e.y_min) + " is not below y_max " + str(e.y_max));
      if (k > 0 && t.edges[k - 1].first_row > e.first_row)
        fail(tri + ": not sorted by first row (edge " + std::to_string(e.edge) + " starts at row " +
             std::to_string(e.first_row) + ", before the edge listed above it)");
      if (e.first_row <= e.last_row) {
        first = any ? std::min(first, e.first_row) : e.first_row;
        last = any ? std::max(last, e.last_row) : e.last_row;
        any = true;
      }
    }
    for (const HorizontalEntry& h : t.horizontal) {
      id(h.edge, "horizontal");
      finite(h.y, tri + ": horizontal edge " + std::to_string(h.edge) + " y");
    }
    s.edges = t.edges;
    // The rows the sweep visits: the table's, clipped to the canvas.
    s.y_first = any ? std::max<i64>(first, 0) : 0;
    s.y_last = any ? std::min<i64>(last, height_ - 1) : -1;
    summary_.edges += static_cast<std::int64_t>(t.edges.size());
    if (thorough_) recompute_edge_table(s, t, tri);
  }

  // Thorough: the table as the fill must build it from the snapped vertices.
  void recompute_edge_table(const TriangleState& s, const EdgeTableEvent& t,
                            const std::string& tri) {
    std::vector<EdgeEntry> want;
    std::vector<int> horizontal;
    auto px = [&](i64 v) { return static_cast<double>(v) / static_cast<double>(scale_); };
    for (std::size_t i = 0; i < s.vertex_count; ++i) {
      const GridPoint a = s.grid[i], b = s.grid[s.next[i]];
      if (a.y == b.y) {
        horizontal.push_back(static_cast<int>(i));
        continue;
      }
      const GridPoint top = a.y < b.y ? a : b, bottom = a.y < b.y ? b : a;
      EdgeEntry e;
      e.edge = static_cast<int>(i);
      e.from = {px(a.x), px(a.y)};
      e.to = {px(b.x), px(b.y)};
      e.y_min = px(top.y), e.y_max = px(bottom.y), e.x_at_y_min = px(top.x);
      e.dx_dy = static_cast<double>(bottom.x - top.x) / static_cast<double>(bottom.y - top.y);
      e.first_row = reference::ceil_div(top.y, scale_);
      e.last_row = closed_ ? reference::floor_div(bottom.y, scale_)
                           : reference::ceil_div(bottom.y, scale_) - 1;
      want.push_back(e);
    }
    std::stable_sort(want.begin(), want.end(), [](const EdgeEntry& a, const EdgeEntry& b) {
      return a.first_row < b.first_row;
    });
    std::vector<int> got_h;
    for (const HorizontalEntry& h : t.horizontal) got_h.push_back(h.edge);
    std::sort(got_h.begin(), got_h.end());
    if (got_h != horizontal)
      fail(tri + ": horizontal edges " + ids(got_h) + ", but the snapped vertices make " +
           ids(horizontal) + " horizontal");
    if (want.size() != t.edges.size())
      fail(tri + ": " + std::to_string(t.edges.size()) + " edges, but the snapped vertices make " +
           std::to_string(want.size()) + " non-horizontal ones");
    for (std::size_t k = 0; k < want.size(); ++k) {
      const EdgeEntry &g = t.edges[k], &w = want[k];
      const std::string en =
          tri + ": entry " + std::to_string(k) + " (edge " + std::to_string(g.edge) + ")";
      if (g.edge != w.edge)
        fail(tri + ": entry " + std::to_string(k) + " is edge " + std::to_string(g.edge) +
             ", but sorted by first row it is edge " + std::to_string(w.edge));
      auto same = [&](double got, double exact, const char* key) {
        if (got != exact)
          fail(en + ": " + key + " is " + str(got) + ", the snapped vertices give " + str(exact));
      };
      same(g.from.x, w.from.x, "from x"), same(g.from.y, w.from.y, "from y");
      same(g.to.x, w.to.x, "to x"), same(g.to.y, w.to.y, "to y");
      same(g.y_min, w.y_min, "y_min"), same(g.y_max, w.y_max, "y_max");
      same(g.x_at_y_min, w.x_at_y_min, "x_at_y_min"), same(g.dx_dy, w.dx_dy, "dx_dy");
      if (g.first_row != w.first_row || g.last_row != w.last_row)
        fail(en + ": rows " + std::to_string(g.first_row) + "…" + std::to_string(g.last_row) +
             ", the snapped vertices give " + std::to_string(w.first_row) + "…" +
             std::to_string(w.last_row));
    }
  }

  const EdgeEntry* entry(const TriangleState& s, int edge) const {
    for (const EdgeEntry& e : s.edges)
      if (e.edge == edge) return &e;
    return nullptr;
  }

  // The pixels of a row's span (or intervals) in columns c.first..c.last.
  static i64 covered_in(const Scanline& r, const RowRange& c) {
    const auto overlap = [&](const Span& p) {
      return std::max<i64>(0, std::min(p.x_end, c.last == INT64_MAX ? p.x_end : c.last + 1) -
                                  std::max(p.x_begin, c.first));
    };
    if (r.intervals) {
      i64 n = 0;
      for (const Interval& i : *r.intervals) n += overlap(i.pixels);
      return n;
    }
    return r.span ? overlap(*r.span) : 0;
  }

  // The pixels a row's span (or intervals) covers, for the pixel-level and count checks.
  static i64 covered(const Scanline& r) {
    if (r.intervals) {
      i64 n = 0;
      for (const Interval& i : *r.intervals) n += i.pixels.size();
      return n;
    }
    return r.span ? r.span->size() : 0;
  }

  // A scanline: in order, its edge sets and points as the edge table says, its span inside the
  // canvas, and (pixel level) the pixel events before it; then it counts toward its triangle.
  void check(const Scanline& r) {
    if (level_ < TraceLevel::scanline) fail("a scanline event in a trace of level triangle");
    TriangleState& s = open(r.triangle, "scanline");
    const auto row = [&] {
      return "triangle " + std::to_string(r.triangle) + ", row " + std::to_string(r.y);
    };
    check_row_order(s, r, row);
    check_edge_sets(s, r, row);
    check_active_points(r, row);
    check_span(r, row);
    const i64 n = covered(r);
    if (level_ == TraceLevel::pixel) check_row_pixels(s, r, n, row);
    if (thorough_) check_exact(s, r, row());
    ++s.scanlines;
    s.span_pixels += n;
    ++summary_.scanlines;
  }

  template <class Row>
  void check_row_order(TriangleState& s, const Scanline& r, const Row& row) {
    if (!s.has_table) fail(row() + ": scanline before the triangle's edge table");
    if (s.last_y && r.y <= *s.last_y)
      fail(row() + ": rows of a triangle must increase, but row " + std::to_string(*s.last_y) +
           " came before");
    if (r.y < s.y_first || r.y > s.y_last)
      fail(row() + ": outside the rows " + std::to_string(s.y_first) + "…" +
           std::to_string(s.y_last) + " its edge table gives (clipped to the canvas)");
    s.last_y = r.y;
  }

  // The active set is what the edge table says for this row; entered/retired are its changes.
  // Compared sorted, in vectors kept for the next row: allocating them for every row is a large
  // part of recording a triangle's trace, which the explorer does on every mouse move.
  template <class Row>
  void check_edge_sets(const TriangleState& s, const Scanline& r, const Row& row) {
    RowSets& sets = row_sets_;
    for (std::vector<int>* v : {&sets.active, &sets.want_active, &sets.want_entered,
                                &sets.want_retired, &sets.entered, &sets.retired})
      v->clear();
    for (const EdgeEntry& e : s.edges) {
      if (e.first_row > e.last_row) continue;
      if (e.first_row <= r.y && r.y <= e.last_row) {
        sets.want_active.push_back(e.edge);
        if (e.first_row == r.y || r.y == s.y_first) sets.want_entered.push_back(e.edge);
      }
      if (e.last_row == r.y - 1 && r.y - 1 >= s.y_first) sets.want_retired.push_back(e.edge);
    }
    for (const EdgeCrossing& a : r.active_edges) {
      finite(a.x, [&] { return row() + ": active edge " + std::to_string(a.edge) + " x"; });
      sets.active.push_back(a.edge);
    }
    sets.entered.assign(r.entered.begin(), r.entered.end());
    sets.retired.assign(r.retired.begin(), r.retired.end());
    for (std::vector<int>* v : {&sets.active, &sets.want_active, &sets.want_entered,
                                &sets.want_retired, &sets.entered, &sets.retired})
      std::sort(v->begin(), v->end());
    if (sets.active != sets.want_active)
      fail(row() + ": active edges " + ids(sets.active) + ", but the edge table makes " +
           ids(sets.want_active) + " active on this row");
    if (sets.entered != sets.want_entered)
      fail(row() + ": entered " + ids(sets.entered) + " disagrees with the active set (edges " +
           ids(sets.want_entered) + " join it on this row)");
    if (sets.retired != sets.want_retired)
      fail(row() + ": retired " + ids(sets.retired) + " disagrees with the active set (edges " +
           ids(sets.want_retired) + " leave it on this row)");
  }

  // Each active point on an active edge (row_sets_.active, sorted by check_edge_sets), by x.
  template <class Row>
  void check_active_points(const Scanline& r, const Row& row) const {
    const std::vector<int>& active = row_sets_.active;
    if (r.active_points.size() != r.active_edges.size())
      fail(row() + ": " + std::to_string(r.active_points.size()) + " active points for " +
           std::to_string(r.active_edges.size()) + " active edges");
    for (std::size_t k = 0; k < r.active_points.size(); ++k) {
      const ActivePoint& p = r.active_points[k];
      const auto pt = [&] { return row() + ": active point " + std::to_string(k); };
      finite(p.x, [&] { return pt() + " x"; });
      color(p.color, [&] { return pt() + ": colour"; });
      if (std::find(active.begin(), active.end(), p.edge) == active.end())
        fail(pt() + " is on edge " + std::to_string(p.edge) + ", which is not active");
      if (k > 0 && r.active_points[k - 1].x > p.x)
        fail(row() + ": active points are not sorted by x (" + str(r.active_points[k - 1].x) +
             " before " + str(p.x) + ")");
    }
  }

  template <class Row>
  void check_span(const Scanline& r, const Row& row) const {
    if (r.span) {
      if (r.span->x_begin > r.span->x_end)
        fail(row() + ": span " + std::to_string(r.span->x_begin) + "…" +
             std::to_string(r.span->x_end) +
             " runs backwards (x_begin > x_end; spans are half-open)");
      if (r.span->x_begin < 0 || r.span->x_end > width_)
        fail(row() + ": span [" + std::to_string(r.span->x_begin) + ", " +
             std::to_string(r.span->x_end) + ") is not inside the canvas [0, " +
             std::to_string(width_) + ")");
    }
    if (r.span_colors) {
      if (!r.span) fail(row() + ": span colours without a span");
      color(r.span_colors->begin, [&] { return row() + ": span colour begin"; });
      color(r.span_colors->end, [&] { return row() + ": span colour end"; });
    }
    if (r.intervals) check_intervals(*r.intervals, row);
  }

  template <class Row>
  void check_intervals(const std::vector<Interval>& intervals, const Row& row) const {
    i64 prev_end = 0;
    for (std::size_t k = 0; k < intervals.size(); ++k) {
      const Interval& iv = intervals[k];
      const auto in = [&] { return row() + ": interval " + std::to_string(k); };
      finite(iv.x_left, [&] { return in() + " x_left"; });
      finite(iv.x_right, [&] { return in() + " x_right"; });
      if (iv.pixels.x_begin > iv.pixels.x_end || iv.pixels.x_begin < prev_end ||
          iv.pixels.x_end > width_)
        fail(in() + ": pixels [" + std::to_string(iv.pixels.x_begin) + ", " +
             std::to_string(iv.pixels.x_end) +
             ") are backwards, overlap the interval before or "
             "leave the canvas");
      prev_end = iv.pixels.x_end;
      if (iv.colors)
        color(iv.colors->begin, [&] { return in() + ": colour"; }),
            color(iv.colors->end, [&] { return in() + ": colour"; });
    }
  }

  // Pixel level: this row's pixels came just before, and are exactly the span's `n` (in the
  // recorded columns, when only some were).
  template <class Row>
  void check_row_pixels(TriangleState& s, const Scanline& r, i64 n, const Row& row) {
    const i64 got = s.pending_y ? static_cast<i64>(s.pending_x.size()) : 0;
    const i64 expected = columns_ ? covered_in(r, *columns_) : n;
    if (s.pending_y && *s.pending_y != r.y)
      fail(row() + ": the pixel events before it are of row " + std::to_string(*s.pending_y));
    if (got != expected)
      fail(row() + ": " + std::to_string(got) + " pixel events for a span of " +
           std::to_string(expected) + " pixels" + (columns_ ? " in the recorded columns" : ""));
    for (i64 x : s.pending_x) {
      bool in = false;
      if (r.intervals) {
        for (const Interval& iv : *r.intervals) in = in || iv.pixels.contains(x);
      } else {
        in = r.span && r.span->contains(x);
      }
      if (!in)
        fail(row() + ": pixel (" + std::to_string(x) + ", " + std::to_string(r.y) +
             ") is outside the span");
    }
    s.pending_y.reset();
    s.pending_x.clear();
  }

  // Thorough: every x and every span from the exact crossings.
  void check_exact(const TriangleState& s, const Scanline& r, const std::string& row) const {
    auto cross = [&](int edge) {
      const GridPoint a = s.grid[edge], b = s.grid[s.next[edge]];
      return a.y < b.y ? crossing(a, b, r.y, scale_) : crossing(b, a, r.y, scale_);
    };
    for (const EdgeCrossing& a : r.active_edges)
      if (const double x = cross(a.edge).x(); a.x != x)
        fail(row + ": active edge " + std::to_string(a.edge) + " at x " + str(a.x) +
             ", but the edge crosses the row at " + str(x));
    for (const ActivePoint& p : r.active_points)
      if (const double x = cross(p.edge).x(); p.x != x)
        fail(row + ": the active point of edge " + std::to_string(p.edge) + " at x " + str(p.x) +
             ", but the edge crosses the row at " + str(x));
    if (r.intervals) {
      for (const Interval& iv : *r.intervals) {
        const Crossing l = cross(iv.left_edge), rr = cross(iv.right_edge);
        const Span want{std::max<i64>(l.ceil(), 0), std::min<i64>(rr.ceil(), width_)};
        if (iv.x_left != l.x() || iv.x_right != rr.x() || iv.pixels.x_begin != want.x_begin ||
            iv.pixels.x_end != want.x_end)
          fail(row + ": interval of edges " + std::to_string(iv.left_edge) + " and " +
               std::to_string(iv.right_edge) + " is [" + std::to_string(iv.pixels.x_begin) + ", " +
               std::to_string(iv.pixels.x_end) + "), the exact crossings give [" +
               std::to_string(want.x_begin) + ", " + std::to_string(want.x_end) + ")");
      }
      return;
    }
    std::optional<Span> want;
    if (r.active_points.size() >= 2) {
      const Crossing l = cross(r.active_points.front().edge),
                     rr = cross(r.active_points.back().edge);
      const Span sp{std::max<i64>(l.ceil(), 0),
                    std::min<i64>(closed_ ? rr.floor() + 1 : rr.ceil(), width_)};
      if (sp.x_begin < sp.x_end) want = sp;
    }
    auto text = [](const std::optional<Span>& sp) {
      std::string s = "none";
      if (sp) (s = "[") += std::to_string(sp->x_begin) + ", " + std::to_string(sp->x_end) + ")";
      return s;
    };
    if (want.has_value() != r.span.has_value() ||
        (want && (want->x_begin != r.span->x_begin || want->x_end != r.span->x_end)))
      fail(row + ": span " + text(r.span) + ", but ceil(x_L) … " +
           (closed_ ? "floor(x_R)" : "ceil(x_R) − 1") + " of the exact crossings, clipped, is " +
           text(want));
  }

  void check(const Pixel& p) {
    if (level_ < TraceLevel::pixel) fail("a pixel event in a trace that is not of level pixel");
    TriangleState& s = open(p.triangle, "pixel");
    const std::string px = "pixel (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                           ") of triangle " + std::to_string(p.triangle);
    if (p.x < 0 || p.x >= width_ || p.y < 0 || p.y >= height_)
      fail(px + " is outside the canvas " + std::to_string(width_) + "x" + std::to_string(height_));
    if (!s.has_table) fail(px + " before the triangle's edge table");
    if (p.y < s.y_first || p.y > s.y_last)
      fail(px + ": row outside the rows " + std::to_string(s.y_first) + "…" +
           std::to_string(s.y_last) + " its edge table gives");
    if (s.last_y && p.y <= *s.last_y)
      fail(px + ": its row's scanline was already narrated (rows must increase)");
    if (s.pending_y && *s.pending_y != p.y)
      fail(px + ": the pixels of row " + std::to_string(*s.pending_y) + " have no scanline event");
    if (!s.pending_x.empty() && s.pending_x.back() >= p.x)
      fail(px + ": pixels of a row must go left to right, each once");
    color(p.color, px + ": colour");
    finite(p.t, px + ": t");
    if (p.depth_test) finite(p.depth_test->depth, px + ": depth");
    s.pending_y = p.y;
    s.pending_x.push_back(p.x);
    ++s.pixel_events;
    ++summary_.pixels;
  }

  void check(const TriangleEnd& e) {
    TriangleState& s = open(e.triangle, "triangle_end");
    const std::string tri = "triangle_end of triangle " + std::to_string(e.triangle);
    if (s.pending_y)
      fail(tri + ": the pixels of row " + std::to_string(*s.pending_y) + " have no scanline event");
    if (e.rows < 0 || e.pixels < 0) fail(tri + ": negative counts");
    if (s.has_table) {
      const i64 rows = std::max<i64>(0, s.y_last - s.y_first + 1);
      if (e.rows != rows)
        fail(tri + ": rows " + std::to_string(e.rows) + ", but its edge table covers " +
             std::to_string(rows) + " rows of the canvas");
      // Every row narrated (no --rows filter cut it): the pixel count is the spans' sum.
      if (level_ >= TraceLevel::scanline && s.scanlines == rows && e.pixels != s.span_pixels)
        fail(tri + ": pixels " + std::to_string(e.pixels) + ", but its spans hold " +
             std::to_string(s.span_pixels));
      if (level_ >= TraceLevel::scanline && e.pixels < s.span_pixels)
        fail(tri + ": pixels " + std::to_string(e.pixels) + ", fewer than its spans hold (" +
             std::to_string(s.span_pixels) + ")");
    }
    s.ended = true;
    // Only `ended` is consulted from now on.
    s.edges = {}, s.grid = {}, s.next = {}, s.pending_x = {};
  }

  void check(const TriangleSkipped& k) {
    auto it = state_.find(k.triangle);
    if (it != state_.end() && it->second.ended)
      fail("triangle_skipped of triangle " + std::to_string(k.triangle) + " after its end");
    if (it != state_.end() && (it->second.has_table || it->second.last_y))
      fail("triangle_skipped of triangle " + std::to_string(k.triangle) +
           ", which was being filled");
    TriangleState& s = state_[k.triangle];
    s.ended = true;
    s.edges = {}, s.grid = {}, s.next = {};
    if (it == state_.end()) ++summary_.triangles;
  }

  void check(const Footer& f) {
    const i64 between = static_cast<i64>(line_) - 2;
    if (f.events != between)
      fail("footer: events " + std::to_string(f.events) + ", but the trace holds " +
           std::to_string(between) + " events between header and footer");
  }

  const std::vector<Event>& events_;
  const std::string& name_;
  const bool thorough_;
  const std::optional<RowRange> columns_;
  std::size_t line_ = 1;
  int width_ = 0, height_ = 0, bits_ = 8;
  TraceLevel level_ = TraceLevel::triangle;
  bool closed_ = false;
  i64 scale_ = 256;
  std::unordered_map<int, TriangleState> state_;
  CheckSummary summary_;
  // A scanline's edge sets, sorted for comparing (check(const Scanline&)), kept from row to row.
  struct RowSets {
    std::vector<int> active, want_active, want_entered, want_retired, entered, retired;
  } row_sets_;
};

}  // namespace

CheckSummary check_consistency(const std::vector<Event>& events, const std::string& name,
                               CheckDepth depth, const std::optional<RowRange>& pixel_columns) {
  return Checker(events, name, depth, pixel_columns).run();
}

}  // namespace scantrace::trace
