#include "bench/timing.hpp"

#include <algorithm>
#include <chrono>

namespace scantrace::bench {
namespace {

double seconds_of(const std::function<void()>& run, int repeats) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < repeats; ++i) run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

std::vector<double> time_interleaved(const std::vector<Job>& jobs, int rounds, double min_seconds) {
  // One warm-up run each (caches, page faults of fresh buffers), which also sizes the repeats.
  std::vector<int> repeats(jobs.size(), 1);
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    const double once = std::max(seconds_of(jobs[j].run, 1), 1e-9);
    repeats[j] = std::max(1, static_cast<int>(min_seconds / once));
  }
  std::vector<std::vector<double>> samples(jobs.size());
  for (int r = 0; r < rounds; ++r)
    for (std::size_t j = 0; j < jobs.size(); ++j)
      samples[j].push_back(seconds_of(jobs[j].run, repeats[j]) / repeats[j]);
  std::vector<double> medians;
  for (std::vector<double>& s : samples) {
    std::nth_element(s.begin(), s.begin() + s.size() / 2, s.end());
    medians.push_back(s[s.size() / 2]);
  }
  return medians;
}

}  // namespace scantrace::bench
