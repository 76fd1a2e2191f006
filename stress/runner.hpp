#pragma once
// The stress run: a time budget shared round-robin by the families (each gets a slice per round,
// so the cheap ones are not starved by meshes and 16,384 px spans, nor the other way round), and
// within a family every rasterizer checks the same cases, generated from (seed, family, index).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "stress/families.hpp"
#include "stress/rasterizer.hpp"
#include "stress/stats.hpp"

namespace scantrace::stress {

struct Progress {
  double elapsed = 0, budget = 0;
  long long cases = 0;             // all families
  long long default_failures = 0;  // failing cases of the default method so far
};

struct RunOptions {
  std::uint64_t seed = 1;
  double seconds = 10;  // the budget; every family still gets at least one case
  std::vector<Family> families{kAllFamilies.begin(), kAllFamilies.end()};
  std::optional<std::uint64_t> only_case;  // run just this case index of each family (replay)
  std::uint64_t max_cases = UINT64_MAX;    // per family
  double colour_tolerance = 1e-4;          // docs/design.md §3
  int reproducers_per_cell = 10;           // for the methods other than the default (which get all)
  std::string default_method = "exact";    // the method whose failures fail the run
  std::function<void(const Progress&)> progress;  // called about once a second
  // Asked after every case: true ends the run there, with the cases checked so far (Ctrl-C in
  // the command: the table of what was checked is still printed).
  std::function<bool()> stop;
};

// Reproducers kept per cell of the default method: all of its failures, unless it is broken so
// badly that listing them would drown the report.
inline constexpr std::size_t kMaxDefaultReproducers = 10000;

struct RunResult {
  std::uint64_t seed = 0;
  double seconds = 0;
  std::vector<CellStats> cells;  // family-major, in the order of the options and rasterizers
  bool default_failed = false;   // the default method failed a check
  long long default_failing_cases = 0;
  bool stopped = false;  // RunOptions::stop ended the run before its budget
};

RunResult run_stress(const RunOptions& options, const std::vector<Rasterizer*>& rasterizers);

}  // namespace scantrace::stress
