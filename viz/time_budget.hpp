#pragma once
// How long a replay may take, checked while it draws: a frame's cost is measured, not assumed.
// --max-frames bounds what a replay writes before it starts; but a frame of a 10⁶-triangle trace at
// 4K, or an HTML page's frames, cost ten times a small one's, so 20,000 frames can be minutes or
// hours. After the first frames the rate so far gives the whole replay's duration; a
// replay that would run past the budget stops there with one line saying the estimate, the frames
// and how to shorten it — before hours are spent, and with nothing written (the sinks remove their
// temporaries when they are not committed).
#include <chrono>
#include <cstddef>
#include <filesystem>

namespace scantrace::viz {

inline constexpr double kDefaultMaxMinutes = 60;

class TimeBudget {
 public:
  TimeBudget(std::filesystem::path out, double max_seconds);
  // `done` of `total` frames drawn so far: throws std::runtime_error when the replay, at the rate
  // measured so far, would take longer than the budget. Estimates are made once a twentieth of
  // the budget (at most a second) has passed, so that the first frames' warm-up does not decide.
  void check(std::size_t done, std::size_t total) const;

 private:
  std::filesystem::path out_;
  double max_seconds_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace scantrace::viz
