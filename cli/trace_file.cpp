#include "cli/trace_file.hpp"

#include <fstream>
#include <sstream>

#include <spdlog/spdlog.h>

namespace scantrace::cli {

trace::Trace load_trace(const std::string& file, bool partial) {
  if (!partial) {
    trace::Trace t = trace::Trace::load(file);
    if (!t.complete())
      throw trace::TraceError(file +
                              ": the trace has no footer, so it is incomplete (an interrupted "
                              "writer or a truncated file): " +
                              t.progress() + "; --partial replays them");
    return t;
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw trace::TraceError(file + ": cannot open trace");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  std::string text = bytes.str();
  if (!text.empty() && text.back() != '\n') {
    const std::size_t last = text.rfind('\n');
    text.erase(last == std::string::npos ? 0 : last + 1);
    spdlog::warn("warning: {}: dropped an unfinished last line", file);
  }
  std::istringstream lines(text);
  trace::Trace t = trace::Trace::parse(lines, file);
  if (!t.complete())
    spdlog::warn("warning: {}: the trace has no footer (cut short): {}; replaying them", file,
                 t.progress());
  return t;
}

}  // namespace scantrace::cli
