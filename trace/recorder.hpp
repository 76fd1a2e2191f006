#pragma once
// The in-memory sink: keeps every event, and on finish() gives them back as a Trace with the same
// query API as a trace read from a file.
#include <utility>
#include <vector>

#include "events.hpp"
#include "trace.hpp"

namespace scantrace::trace {

class Recorder {
 public:
  explicit Recorder(const Header& header) {
    events_.emplace_back(std::in_place_type<Header>, header);
  }
  void write(const Event& e) { events_.push_back(e); }
  Trace finish(const Footer& footer) {
    events_.emplace_back(std::in_place_type<Footer>, footer);
    return Trace::from_events(std::move(events_), "(memory)");
  }

 private:
  std::vector<Event> events_;
};

}  // namespace scantrace::trace
