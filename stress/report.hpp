#pragma once
// The stress report: the Markdown table (rows: family × method) and the one-line reproducers.
#include <string>

#include "stress/runner.hpp"
#include "stress/stats.hpp"
#include "stress/stress_case.hpp"

namespace scantrace::stress {

// The table, one row per cell, preceded by nothing and followed by a blank line.
std::string markdown_table(const RunResult& result);

// One line naming a failing case completely: method, family, seed, index, vertex order, the first
// problem met, and the vertices and colours with full precision (%.17g round-trips a double), plus
// the commands that replay it.
std::string reproducer(const StressCase& c, const std::string& method, const CaseResult& r);

}  // namespace scantrace::stress
