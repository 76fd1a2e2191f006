#include "stress/runner.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <span>

#include "stress/checks.hpp"
#include "stress/reference_window.hpp"
#include "stress/report.hpp"
#include "stress/stress_case.hpp"

namespace scantrace::stress {
namespace {

using Clock = std::chrono::steady_clock;

class Run {
 public:
  Run(const RunOptions& o, const std::vector<Rasterizer*>& rasterizers)
      : o_(o), rasterizers_(rasterizers), checker_(o.colour_tolerance) {
    for (Family f : o.families)
      for (const Rasterizer* r : rasterizers) {
        CellStats cell;
        cell.family = f;
        cell.method = r->name();
        cell.mesh = f == Family::meshes;
        cell.shades = r->shades() && !cell.mesh;
        cells_.push_back(cell);
      }
  }

  // Checks case `index` of family number `fi` with every rasterizer.
  void run_case(std::size_t fi, std::uint64_t index) {
    const StressCase c = generate(o_.families[fi], o_.seed, index);
    // The reference is computed once per fill rule in use, and shared by the rasterizers.
    std::optional<ReferenceWindow> refs[2];
    const auto reference = [&](FillRule rule) -> const ReferenceWindow& {
      std::optional<ReferenceWindow>& slot = refs[rule == FillRule::closed ? 1 : 0];
      if (!slot) {
        if (c.is_mesh())
          slot.emplace(c.width, c.height, c.region, std::span<const Color>{}, rule);
        else
          slot.emplace(c.width, c.height, c.triangles.front().v, c.triangles.front().c, rule);
      }
      return *slot;
    };
    for (std::size_t ri = 0; ri < rasterizers_.size(); ++ri) {
      Rasterizer& r = *rasterizers_[ri];
      const CaseResult result = c.is_mesh() ? checker_.check_mesh(r, c, reference(r.rule()))
                                            : checker_.check_triangle(r, c, reference(r.rule()));
      CellStats& cell = cells_[fi * rasterizers_.size() + ri];
      cell.add(result, static_cast<long long>(c.triangles.size()), o_.colour_tolerance);
      if (result.failed(o_.colour_tolerance)) {
        // Every failure of the default method gets its reproducer (up to a sanity bound against
        // a systematic breakage printing millions of lines); the others the first few per cell.
        const bool is_default = cell.method == o_.default_method;
        if (is_default) ++default_failures_;
        const std::size_t cap =
            is_default ? kMaxDefaultReproducers : static_cast<std::size_t>(o_.reproducers_per_cell);
        if (cell.reproducers.size() < cap)
          cell.reproducers.push_back(reproducer(c, cell.method, result));
      }
    }
  }

  RunResult finish(double seconds) {
    RunResult out;
    out.seed = o_.seed;
    out.seconds = seconds;
    out.cells = std::move(cells_);
    out.default_failing_cases = default_failures_;
    for (const CellStats& cell : out.cells)
      if (cell.method == o_.default_method && cell.failed(o_.colour_tolerance))
        out.default_failed = true;
    return out;
  }

  long long default_failures() const { return default_failures_; }

 private:
  const RunOptions& o_;
  const std::vector<Rasterizer*>& rasterizers_;
  Checker checker_;
  std::vector<CellStats> cells_;
  long long default_failures_ = 0;
};

}  // namespace

RunResult run_stress(const RunOptions& o, const std::vector<Rasterizer*>& rasterizers) {
  const Clock::time_point start = Clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  Run run(o, rasterizers);
  const std::size_t n = o.families.size();
  std::vector<std::uint64_t> next(n, o.only_case.value_or(0)), done_cases(n, 0);
  // About 20 rounds over the budget, each family's slice between 20 ms and 1 s.
  const double slice =
      std::clamp(o.seconds / (20.0 * static_cast<double>(std::max<std::size_t>(n, 1))), 0.02, 1.0);
  const std::uint64_t limit = o.only_case ? 1 : o.max_cases;
  long long cases = 0;
  double last_report = 0;
  bool stopped = false;
  for (int round = 0; !stopped; ++round) {
    bool ran = false;
    for (std::size_t fi = 0; fi < n; ++fi) {
      if (done_cases[fi] >= limit) continue;
      // The first round runs every family once even when the budget is already spent.
      if (round > 0 && elapsed() >= o.seconds) break;
      const double slice_start = elapsed();
      do {
        run.run_case(fi, next[fi]++);
        ++done_cases[fi];
        ++cases;
        ran = true;
        stopped = o.stop && o.stop();
      } while (!stopped && done_cases[fi] < limit && elapsed() - slice_start < slice &&
               elapsed() < o.seconds);
      if (stopped) break;
      if (o.progress && elapsed() - last_report >= 1.0) {
        last_report = elapsed();
        o.progress({last_report, o.seconds, cases, run.default_failures()});
      }
    }
    if (!ran || elapsed() >= o.seconds) break;
  }
  RunResult result = run.finish(elapsed());
  result.stopped = stopped;
  return result;
}

}  // namespace scantrace::stress
