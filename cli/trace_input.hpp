#pragma once
// Loading a trace named on the command line, for every subcommand that reads one (replay, check):
// a trace without its footer was cut short, which is an error unless --partial asks to use the
// complete lines it holds (an unfinished last line is then dropped, with a warning).
#include <string>

#include "trace/trace.hpp"

namespace scantrace::cli {

trace::Trace load_trace(const std::string& file, bool partial);

}  // namespace scantrace::cli
