#pragma once
#include <chrono>

namespace scantrace::cli {

// Milliseconds since construction, for the one-line reports of the subcommands.
class Stopwatch {
 public:
  double ms() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_)
        .count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace scantrace::cli
