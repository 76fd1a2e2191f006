#pragma once
// Consistency of a trace: a trace is data people hand around and edit, and replaying a record that
// contradicts itself would teach something that never happened. Two depths:
//
//   cheap     run on every load (Trace::from_events: replay, explain, demo, queries). A constant
//             amount of work per event, no exact arithmetic: who may speak when (a scanline or
//             pixel of a triangle that was begun and not yet ended), rows strictly increasing
//             and inside the edge table's rows and the canvas, spans half-open and on the canvas,
//             active points sorted and finite, colours finite and in [0, 1], entered/retired
//             agreeing with the active set, row and pixel counts of triangle_end and the footer.
//   thorough  `scantrace check TRACE` adds what needs exact arithmetic on the snapped vertices:
//             every edge table entry recomputed from them, every active edge's and active
//             point's x equal to the edge's exact crossing with the row, every span equal to
//             ceil(x_L) … ceil(x_R) − 1 (closed rule: … floor(x_R)), clipped to the canvas.
//
// The first contradiction is thrown as a TraceError "<name>:<line>: <what>" (the line of the event
// in the file: events[i] is line i + 1). A trace cut short (no footer, --partial) is checked as
// far as it goes.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "events.hpp"
#include "trace_filter.hpp"

namespace scantrace::trace {

enum class CheckDepth { cheap, thorough };

// What was looked at, for `scantrace check`'s summary.
struct CheckSummary {
  std::int64_t events = 0, triangles = 0, scanlines = 0, pixels = 0, edges = 0;
};

// Throws TraceError at the first contradiction. `events` starts with the header (checked by
// Trace::from_events before this is called).
// `pixel_columns`: the pixel events were recorded for these columns only (TraceFilter::columns,
// an in-memory recording such as `why`'s); each row's pixel events are then exactly its span's
// pixels in those columns.
CheckSummary check_consistency(const std::vector<Event>& events, const std::string& name,
                               CheckDepth depth,
                               const std::optional<RowRange>& pixel_columns = std::nullopt);

}  // namespace scantrace::trace
