#pragma once
// Reading a trace file for `replay` and `step`, with --partial for a trace that was cut short.
#include <string>

#include "trace/trace.hpp"

namespace scantrace::cli {

// A trace without its footer was cut short. By default that is an error — a video of half a fill
// that looks complete would mislead; with `partial` the complete lines are kept (an unfinished
// last line is dropped) and a warning says so. Throws trace::TraceError naming the file.
trace::Trace load_trace(const std::string& file, bool partial);

}  // namespace scantrace::cli
