#pragma once
// Ctrl-C and `kill` (SIGINT, SIGTERM) during a long run: nothing is left under an output's final
// name, and no temporary file is left behind.
//
// The first signal only sets a flag. The long loops (writing a trace event by event, writing
// video frames) call check_interrupt(), which throws Interrupted; the exception unwinds through
// AtomicFile and the frame sinks, whose destructors remove their temporaries, and the command
// exits with 128 + the signal number (130, 143). A second signal is for a run that does not reach
// a check in time: the handler itself removes the registered temporary files (unlink is
// async-signal-safe) and exits at once with the same status.
#include <filesystem>
#include <stdexcept>

namespace scantrace {

class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal);
  int signal() const { return signal_; }
  int exit_status() const { return 128 + signal_; }

 private:
  int signal_;
};

// Installs the SIGINT and SIGTERM handlers (the command line does, once, at start).
void install_interrupt_handlers();

// The signal received so far (0: none).
int interrupt_signal();

// Throws Interrupted when a signal has arrived.
inline void check_interrupt() {
  if (const int s = interrupt_signal()) throw Interrupted(s);
}

// Temporary files the handler removes on a second signal. Registration is by the writers of
// io/atomic_write.hpp and the video writer; paths longer than 4095 bytes, or more than 32 at
// once, are not registered (and are then left to the first-signal path).
void register_temporary(const std::filesystem::path& file);
void unregister_temporary(const std::filesystem::path& file);

}  // namespace scantrace
