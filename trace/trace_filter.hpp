#pragma once
// What to trace: the level of detail, which triangles, which rows, and how many events at most.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "src/option_table.hpp"
#include "src/tracer.hpp"

namespace scantrace::trace {

// A set of triangle indices written as "3,17,40-45" (ranges inclusive).
class IndexSet {
 public:
  IndexSet() = default;
  // Throws std::invalid_argument naming the offending item.
  static IndexSet parse(const std::string& text);
  // The set of `indices` (each >= 0; any order, repeats allowed).
  static IndexSet of(const std::vector<int>& indices);
  bool contains(int i) const;
  const std::vector<std::pair<int, int>>& ranges() const { return ranges_; }

 private:
  void merge();
  std::vector<std::pair<int, int>> ranges_;  // sorted, inclusive
};

// Rows A…B inclusive, written "A:B"; either side may be omitted ("100:" or ":50").
struct RowRange {
  std::int64_t first = INT64_MIN, last = INT64_MAX;
  static RowRange parse(const std::string& text);  // throws std::invalid_argument
  bool contains(std::int64_t y) const { return y >= first && y <= last; }
};

struct TraceFilter {
  TraceLevel level = option_table<TraceLevel>().default_value;
  std::optional<IndexSet> triangles{};       // none: every triangle
  std::optional<RowRange> rows{};            // none: every row (scanline and pixel events only)
  // Columns of the pixel events kept (none: every column). `why` keeps one: a face's row there
  // costs one event instead of one per pixel of its span (65 KB a face, 722 MB for 10k faces).
  std::optional<RowRange> columns{};
  std::optional<std::int64_t> max_events{};  // cap on the events between header and footer
  // Cap on the size of a written trace: the header and event lines stay within it (the footer
  // line, under 100 bytes, comes on top). Only sinks that write bytes (JSON Lines) apply it.
  std::optional<std::int64_t> max_bytes{};
};

const char* to_string(TraceLevel level);
TraceLevel parse_level(const std::string& text);  // throws std::invalid_argument

}  // namespace scantrace::trace
