#pragma once
// Side-by-side timing: every job of a comparison runs once per round, in the same order, for all
// rounds, and each job's time is the median of its rounds. The machines are shared and noisy;
// interleaving makes a burst of load hit all the jobs of a round alike, so ratios between jobs
// are far steadier than their absolute times.
#include <functional>
#include <string>
#include <vector>

namespace scantrace::bench {

struct Job {
  std::string name;
  std::function<void()> run;
};

// Median seconds per run of each job. A job faster than `min_seconds` is repeated within a round
// until the round's sample is long enough to time (the sample is then divided by the repeats).
std::vector<double> time_interleaved(const std::vector<Job>& jobs, int rounds,
                                     double min_seconds = 2e-3);

}  // namespace scantrace::bench
