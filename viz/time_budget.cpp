#include "viz/time_budget.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <spdlog/fmt/fmt.h>

namespace scantrace::viz {

TimeBudget::TimeBudget(std::filesystem::path out, double max_seconds)
    : out_(std::move(out)), max_seconds_(max_seconds) {}

void TimeBudget::check(std::size_t done, std::size_t total) const {
  if (done == 0 || done >= total) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (elapsed < std::min(1.0, max_seconds_ / 20)) return;
  const double per_frame = elapsed / static_cast<double>(done);
  const double estimate = per_frame * static_cast<double>(total);
  if (estimate <= max_seconds_) return;
  const std::string duration = estimate < 120 ? fmt::format("{:.1f} seconds", estimate)
                                              : fmt::format("{:.0f} minutes", estimate / 60);
  throw std::runtime_error(fmt::format(
      "{}: the replay would take about {} ({} frames at {:.0f} ms each so far), more than the "
      "budget of {:g} minutes (--max-minutes); choose fewer steps (--steps A:B, --rows-per-step "
      "N, fewer triangles), a smaller --video-size, or raise the budget",
      out_.string(), duration, total, per_frame * 1000, max_seconds_ / 60));
}

}  // namespace scantrace::viz
