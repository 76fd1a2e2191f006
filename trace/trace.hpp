#pragma once
// A trace, read from a .jsonl file or recorded in memory, and the questions one asks of it:
//
//   Trace t = Trace::load("triangle.jsonl");
//   t.triangles();                        // the triangles traced, in order
//   t.edge_table(0).edges[1].dx_dy;       // the edge table of triangle 0
//   t.scanline(0, 42).active_points;      // triangle 0 at row 42: active edges, points, span…
//   t.pixel_history(200, 200).final();    // who wrote pixel (200, 200), in order, and the last
//                                         // (final() throws for a pixel nobody wrote)
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "events.hpp"
#include "io/input_error.hpp"
#include "src/scene.hpp"
#include "trace_filter.hpp"

namespace scantrace::trace {

// A malformed trace: one line naming the file and, when it is about one line, its number
// ("t.jsonl:3: not valid JSON …"). It is bad input data, so it is an InputError (exit status 1).
class TraceError : public InputError {
 public:
  explicit TraceError(const std::string& message) : InputError(message, "", "") {}
};

// progress() of a trace holding `events` (header first).
std::string progress_of(const std::vector<Event>& events);

struct PixelWrite {
  int triangle = 0;
  Color color;
  bool from_pixel_event = false;  // false: reconstructed from the scanline's span and colours
};

struct PixelHistory {
  std::vector<PixelWrite> writes;  // in drawing order
  bool empty() const { return writes.empty(); }
  // The write that is visible in the image (the last one); throws if nobody wrote the pixel.
  const PixelWrite& final() const;
};

class Trace {
 public:
  // Refuses a file whose events would not fit in the memory available (its size times what an
  // event costs in memory over its text, see kMemoryPerTraceByte), before reading it.
  // drop_unfinished_last_line: a last line without its newline (a writer cut off mid-line) is
  // dropped instead of being an error (--partial); dropped_last_line() then says so.
  static Trace load(const std::filesystem::path& path, bool drop_unfinished_last_line = false);
  static Trace parse(std::istream& in, const std::string& name,
                     bool drop_unfinished_last_line = false);
  // Checks the structure (header first, version, footer last) and indexes the events.
  // `pixel_columns`: the pixel events were recorded for these columns only (TraceFilter::columns).
  static Trace from_events(std::vector<Event> events, const std::string& name,
                           const std::optional<RowRange>& pixel_columns = std::nullopt);

  const Header& header() const;
  const std::vector<Event>& events() const { return events_; }
  bool complete() const { return footer_.has_value(); }  // false: the writer was interrupted
  // How far the trace got, for messages about an incomplete one: "it holds the header and 812
  // events, the last at triangle 17, row 212".
  std::string progress() const;
  bool truncated() const { return footer_ && footer_->truncated; }
  bool dropped_last_line() const { return dropped_last_line_; }
  const std::optional<Footer>& footer() const { return footer_; }

  std::vector<int> triangles() const;  // traced (begun or skipped), in order of appearance
  bool has_triangle(int t) const { return index_.count(t) > 0; }
  // The accessors below throw std::out_of_range naming the trace when the event is absent; the
  // find_ ones return nullptr instead (a filtered or interrupted trace legitimately lacks some).
  const TriangleBegin* find_triangle_begin(int t) const;
  const EdgeTableEvent* find_edge_table(int t) const;
  const Scanline* find_scanline(int t, i64 y) const;
  const TriangleBegin& triangle_begin(int t) const;
  const EdgeTableEvent& edge_table(int t) const;
  const Scanline& scanline(int t, i64 y) const;
  bool has_scanline(int t, i64 y) const;
  std::vector<const Scanline*> scanlines(int t) const;  // by increasing y
  std::vector<const Pixel*> pixels(int t) const;        // pixel events, in order
  // The same limited to rows first_row..last_row, at the cost of those rows (a replay frame's).
  std::vector<const Scanline*> scanlines(int t, i64 first_row, i64 last_row) const;
  std::vector<const Pixel*> pixels(int t, i64 first_row, i64 last_row) const;
  std::optional<TriangleEnd> triangle_end(int t) const;
  std::optional<TriangleSkipped> skipped(int t) const;
  PixelHistory pixel_history(i64 x, i64 y) const;

 private:
  struct TriangleIndex {
    std::optional<std::size_t> begin, edge_table, end, skipped;
    std::map<i64, std::size_t> scanlines;
    std::vector<std::size_t> pixels;
    bool pixels_by_row = true;  // their rows never decrease: pixels(t, rows) bisects
  };
  const TriangleIndex& at(int t) const;

  std::string name_;
  std::vector<Event> events_;
  std::optional<Footer> footer_;
  bool dropped_last_line_ = false;
  std::vector<int> order_;
  std::map<int, TriangleIndex> index_;
  std::map<i64, std::vector<std::size_t>> rows_;  // scanline events by row, in order
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> pixel_events_;  // by (x, y)
};

}  // namespace scantrace::trace
