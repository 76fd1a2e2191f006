#include "viz/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace scantrace::viz {
namespace {

// Nothing is shown before this much time has passed: most replays are over by then.
constexpr auto kQuietStart = std::chrono::milliseconds(1500);
constexpr auto kBarInterval = std::chrono::milliseconds(100);
constexpr auto kLineInterval = std::chrono::seconds(5);

}  // namespace

StderrProgress::StderrProgress(std::string what, std::string unit)
    : what_(std::move(what)), unit_(std::move(unit)), terminal_(::isatty(STDERR_FILENO) == 1) {}

void StderrProgress::update(std::size_t done, std::size_t total) {
  done_ = done;
  total_ = total;
  const auto now = Clock::now();
  if (now - start_ < kQuietStart || total == 0) return;
  const int percent = static_cast<int>(100.0 * static_cast<double>(done) / total);
  if (terminal_) {
    if (drawn_ && now - last_ < kBarInterval && done < total) return;
    constexpr int kWidth = 30;
    const int filled = percent * kWidth / 100;
    std::fprintf(stderr, "\rscantrace: %s [%.*s%*s] %3d%%  %zu/%zu %s", what_.c_str(), filled,
                 "##############################", kWidth - filled, "", percent, done, total,
                 unit_.c_str());
    std::fflush(stderr);
  } else {
    if (drawn_ && now - last_ < kLineInterval) return;
    if (!drawn_ && now - start_ < kLineInterval) return;
    std::fprintf(stderr, "scantrace: %s: %zu/%zu %s (%d%%)\n", what_.c_str(), done, total,
                 unit_.c_str(), percent);
  }
  drawn_ = true;
  last_ = now;
}

void StderrProgress::finish() {
  if (drawn_ && terminal_) {
    update(total_, total_);
    std::fputc('\n', stderr);
  }
  drawn_ = false;
}

}  // namespace scantrace::viz
