#pragma once
// The tracer that turns the fill's hooks (src/tracer.hpp) into trace events and hands them to a
// sink — an in-memory Recorder or a JsonlWriter. Filters are applied before any event is built, so
// tracing one triangle of a 10,000-triangle scene costs one rendering plus that one triangle.
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "events.hpp"
#include "src/depth_test.hpp"
#include "src/tracer.hpp"
#include "trace_filter.hpp"

namespace scantrace::trace {

// The header of a trace of a `width`×`height` canvas filled with `options` at `level`.
Header make_header(int width, int height, const FillOptions& options, TraceLevel level);

// Event conversions from the fill's hook payloads.
TriangleBegin to_event(const PolygonSetup& s);
EdgeTableEvent to_event(const EdgeTableView& v);
Scanline to_event(const ScanlineStep& s);

// A Sink provides `void write(const Event&)` and `R finish(const Footer&)`; one that writes bytes
// may also provide `bool write_within(const Event&, std::int64_t max_bytes)`, which writes the
// event only if the output stays within max_bytes (TraceFilter::max_bytes).
template <class Sink>
class EventTracer {
 public:
  static constexpr TraceLevel max_level = TraceLevel::pixel;

  EventTracer(Sink sink, TraceFilter filter) : sink_(std::move(sink)), filter_(std::move(filter)) {}

  bool wants_triangle(int t) const {
    return !full_ && filter_.level >= TraceLevel::triangle &&
           (!filter_.triangles || filter_.triangles->contains(t));
  }
  bool wants_scanline(int, i64 y) const {
    return !full_ && filter_.level >= TraceLevel::scanline &&
           (!filter_.rows || filter_.rows->contains(y));
  }
  bool wants_pixels(int, i64) const { return !full_ && filter_.level >= TraceLevel::pixel; }

  void triangle_begin(const PolygonSetup& s) { emit(to_event(s)); }
  void edge_table(const EdgeTableView& v) { emit(to_event(v)); }
  void scanline(const ScanlineStep& s) { emit(to_event(s)); }
  void pixel(int t, i64 x, i64 y, Color c, double w) {
    if (wants_column(x)) emit(Pixel{t, x, y, c, w, {}});
  }
  void pixel(int t, i64 x, i64 y, Color c, double w, const DepthTest& d) {
    if (!wants_column(x)) return;
    emit(Pixel{t, x, y, c, w,
               PixelDepthTest{d.passed, d.depth,
                              std::isinf(d.stored) ? std::nullopt : std::optional(d.stored)}});
  }
  void triangle_end(int t, i64 rows, i64 pixels) { emit(TriangleEnd{t, rows, pixels}); }
  void triangle_skipped(int t, SkipReason r) { emit(TriangleSkipped{t, to_string(r)}); }

  Footer footer() const { return {events_, truncated_}; }
  bool truncated() const { return truncated_; }
  // Ends the trace (the sink writes the footer) and returns what the sink makes of it.
  auto finish() { return sink_.finish(footer()); }
  Sink& sink() { return sink_; }

 private:
  bool wants_column(i64 x) const { return !filter_.columns || filter_.columns->contains(x); }

  void emit(const Event& e) {
    if (full_) return;
    if (filter_.max_events && events_ >= *filter_.max_events) {
      // The cap is reached: from now on every wants_* answers no, so the fill stops building
      // events at all, and the footer says the trace is incomplete.
      full_ = truncated_ = true;
      return;
    }
    if constexpr (requires(Sink & sink) { sink.write_within(e, std::int64_t{}); }) {
      if (filter_.max_bytes) {
        if (!sink_.write_within(e, *filter_.max_bytes))
          full_ = truncated_ = true;
        else
          ++events_;
        return;
      }
    }
    ++events_;
    sink_.write(e);
  }

  Sink sink_;
  TraceFilter filter_;
  i64 events_ = 0;
  bool full_ = false, truncated_ = false;
};

}  // namespace scantrace::trace
