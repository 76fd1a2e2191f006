#pragma once
// Look-ups into a trace for the frames, which show what there is: a filtered or interrupted trace
// legitimately lacks some events (the Trace's find_ accessors answer nullptr then).
#include <string>

#include <spdlog/fmt/fmt.h>

#include "trace/trace.hpp"

namespace scantrace::viz {

inline const trace::TriangleBegin* find_begin(const trace::Trace& t, int triangle) {
  return t.find_triangle_begin(triangle);
}

inline const trace::EdgeTableEvent* find_edge_table(const trace::Trace& t, int triangle) {
  return t.find_edge_table(triangle);
}

inline const trace::Scanline* find_scanline(const trace::Trace& t, int triangle, trace::i64 y) {
  return t.find_scanline(triangle, y);
}

inline const trace::EdgeEntry* find_edge(const trace::EdgeTableEvent* table, int id) {
  if (!table) return nullptr;
  for (const trace::EdgeEntry& e : table->edges)
    if (e.edge == id) return &e;
  return nullptr;
}

// The polygon coverage is decided on: the snapped vertices (the given ones in older traces).
inline const std::vector<Vec2>& polygon_of(const trace::TriangleBegin& b) {
  return b.snapped.empty() ? b.vertices : b.snapped;
}

// The closed contours of the polygon: one for a triangle or convex polygon, several for a general
// polygon with holes (its `contours` list the vertex indices of each).
inline std::vector<std::vector<Vec2>> contours_of(const trace::TriangleBegin& b) {
  const std::vector<Vec2>& p = polygon_of(b);
  if (b.contours.empty()) return {p};
  std::vector<std::vector<Vec2>> out;
  for (const std::vector<int>& c : b.contours) {
    std::vector<Vec2>& o = out.emplace_back();
    for (int i : c)
      if (i >= 0 && static_cast<std::size_t>(i) < p.size()) o.push_back(p[i]);
  }
  return out;
}

// The vertex edge `id` runs to: the next vertex of its contour.
inline int next_vertex(const trace::TriangleBegin* b, int id) {
  if (b)
    for (const std::vector<int>& c : b->contours)
      for (std::size_t k = 0; k < c.size(); ++k)
        if (c[k] == id) return c[(k + 1) % c.size()];
  const int n = static_cast<int>(b && !b->vertices.empty() ? b->vertices.size() : 3);
  return (id + 1) % n;
}

inline std::string edge_name(int id, const trace::TriangleBegin* b) {
  return fmt::format("e{} v{}-v{}", id, id, next_vertex(b, id));
}

// "e1 v1-v2": edge i runs from vertex i to vertex (i + 1) mod n.
inline std::string edge_name(int id, std::size_t vertices = 3) {
  const int n = static_cast<int>(vertices == 0 ? 3 : vertices);
  return fmt::format("e{} v{}-v{}", id, id, (id + 1) % n);
}

}  // namespace scantrace::viz
