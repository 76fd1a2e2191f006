#pragma once
// Loading a trace named on the command line, for every subcommand that reads one (replay, check):
// a trace without its footer was cut short, which is an error unless --partial asks to use the
// complete lines it holds (an unfinished last line is then dropped, with a warning).
#include <string>

#include "trace/trace.hpp"

namespace scantrace::cli {

trace::Trace load_trace(const std::string& file, bool partial);

// Warns when the trace `file` was cut by a budget of `scantrace trace`. The file does not record
// which one, so both are named: the warning blamed --max-events for a trace cut by --max-bytes.
void warn_if_truncated(const trace::Trace& t, const std::string& file);

}  // namespace scantrace::cli
