#pragma once
// A pixel-level tracer that keeps copies of everything the fill reports, for tests that check the
// hooks against what the fill actually wrote.
#include <map>
#include <set>
#include <vector>

#include "src/tracer.hpp"

namespace scantrace::testing {

struct RecordedScanline {
  int triangle = 0;
  i64 y = 0;
  std::vector<int> entered, retired;
  std::vector<EdgeCrossing> active_edges;
  std::vector<ActivePoint> active_points;
  bool has_span = false;
  i64 x_begin = 0, x_end = 0;
  bool has_span_colors = false;
  Color span_begin, span_end;
};

struct RecordedPixel {
  int triangle = 0;
  i64 x = 0, y = 0;
  Color color;
  double t = 0;
};

struct RecordingTracer {
  static constexpr TraceLevel max_level = TraceLevel::pixel;

  std::set<int> only;  // empty: every triangle
  std::vector<int> begun, ended;
  std::map<int, SkipReason> skipped;
  std::map<int, std::vector<Edge>> edge_tables;
  std::vector<RecordedScanline> scanlines;
  std::vector<RecordedPixel> pixels;

  bool wants_triangle(int t) const { return only.empty() || only.count(t) > 0; }
  bool wants_scanline(int, i64) const { return true; }
  bool wants_pixels(int, i64) const { return true; }
  void triangle_begin(const PolygonSetup& s) { begun.push_back(s.face); }
  void edge_table(const EdgeTableView& v) { edge_tables[v.face] = v.table->edges(); }
  void triangle_end(int t, i64, i64) { ended.push_back(t); }
  void triangle_skipped(int t, SkipReason r) { skipped[t] = r; }
  void scanline(const ScanlineStep& s) {
    scanlines.push_back({s.face,
                         s.y,
                         {s.entered.begin(), s.entered.end()},
                         {s.retired.begin(), s.retired.end()},
                         {s.active_edges.begin(), s.active_edges.end()},
                         {s.active_points.begin(), s.active_points.end()},
                         s.has_span,
                         s.span.x_begin,
                         s.span.x_end,
                         s.has_span && s.span.has_colors,
                         s.span.begin,
                         s.span.end});
  }
  void pixel(int t, i64 x, i64 y, Color c, double w) { pixels.push_back({t, x, y, c, w}); }
};

}  // namespace scantrace::testing
