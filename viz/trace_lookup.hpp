#pragma once
// Optional look-ups into a trace: the Trace accessors throw when an event is absent, but a
// filtered or interrupted trace legitimately lacks some, and a frame then shows what there is.
#include <string>

#include <spdlog/fmt/fmt.h>

#include "trace/trace.hpp"

namespace scantrace::viz {

inline const trace::TriangleBegin* find_begin(const trace::Trace& t, int triangle) {
  if (triangle < 0 || !t.has_triangle(triangle)) return nullptr;
  try {
    return &t.triangle_begin(triangle);
  } catch (const std::out_of_range&) {
    return nullptr;
  }
}

inline const trace::EdgeTableEvent* find_edge_table(const trace::Trace& t, int triangle) {
  if (triangle < 0 || !t.has_triangle(triangle)) return nullptr;
  try {
    return &t.edge_table(triangle);
  } catch (const std::out_of_range&) {
    return nullptr;
  }
}

inline const trace::Scanline* find_scanline(const trace::Trace& t, int triangle, trace::i64 y) {
  return t.has_scanline(triangle, y) ? &t.scanline(triangle, y) : nullptr;
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

// "e1 v1-v2": edge i runs from vertex i to vertex (i + 1) mod n.
inline std::string edge_name(int id, std::size_t vertices = 3) {
  const int n = static_cast<int>(vertices == 0 ? 3 : vertices);
  return fmt::format("e{} v{}-v{}", id, id, (id + 1) % n);
}

}  // namespace scantrace::viz
