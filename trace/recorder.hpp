#pragma once
// The in-memory sink: keeps every event, and on finish() gives them back as a Trace with the same
// query API as a trace read from a file.
#include <optional>
#include <utility>
#include <vector>

#include "events.hpp"
#include "io/interrupt.hpp"
#include "trace.hpp"
#include "trace_filter.hpp"

namespace scantrace::trace {

class Recorder {
 public:
  // `pixel_columns`: the filter's columns (TraceFilter::columns), for the consistency checks.
  explicit Recorder(const Header& header, std::optional<RowRange> pixel_columns = std::nullopt)
      : columns_(pixel_columns) {
    events_.emplace_back(std::in_place_type<Header>, header);
  }
  void write(const Event& e) {
    // A long recording (why over 10^5 faces, a trace in memory) stops on SIGINT/SIGTERM here, as
    // the JSON Lines writer does on every event.
    if ((events_.size() & 1023) == 0) check_interrupt();
    events_.push_back(e);
  }
  Trace finish(const Footer& footer) {
    events_.emplace_back(std::in_place_type<Footer>, footer);
    return Trace::from_events(std::move(events_), "(memory)", columns_);
  }

 private:
  std::vector<Event> events_;
  std::optional<RowRange> columns_;
};

}  // namespace scantrace::trace
