#pragma once
// Progress of a long render on stderr: a bar redrawn in place when stderr is a terminal, plain
// lines every few seconds otherwise (a log file should not fill with carriage returns). Short
// renders print nothing.
#include <chrono>
#include <cstddef>
#include <string>

namespace scantrace::viz {

class Progress {
 public:
  virtual ~Progress() = default;
  virtual void update(std::size_t done, std::size_t total) = 0;
  virtual void finish() = 0;
};

class StderrProgress : public Progress {
 public:
  // `what` names the work in the lines ("triangle.mp4"); `unit` what is counted ("frames").
  StderrProgress(std::string what, std::string unit);
  void update(std::size_t done, std::size_t total) override;
  void finish() override;

 private:
  using Clock = std::chrono::steady_clock;
  std::string what_, unit_;
  bool terminal_;
  Clock::time_point start_ = Clock::now(), last_ = start_;
  bool drawn_ = false;
  std::size_t done_ = 0, total_ = 0;
};

}  // namespace scantrace::viz
