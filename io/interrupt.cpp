#include "io/interrupt.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <string>

namespace scantrace {
namespace {

// Everything the handler touches is lock-free atomics or fixed storage: no allocation, no lock.
std::atomic<int> received{0};

struct Slot {
  std::atomic<bool> used{false};
  char path[4096];
};
std::array<Slot, 32> slots;

void write_stderr(const char* s) {
  const ssize_t ignored = ::write(STDERR_FILENO, s, std::strlen(s));
  (void)ignored;
}

extern "C" void on_signal(int signal) {
  int none = 0;
  if (received.compare_exchange_strong(none, signal)) return;  // the first: the loops stop
  for (Slot& slot : slots)
    if (slot.used.load()) ::unlink(slot.path);
  write_stderr("scantrace: interrupted again; temporary files removed, exiting now\n");
  ::_exit(128 + received.load());
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(std::string("interrupted by ") +
                         (signal == SIGINT    ? "SIGINT"
                          : signal == SIGTERM ? "SIGTERM"
                                              : "signal " + std::to_string(signal)) +
                         "; no output was written under its final name"),
      signal_(signal) {}

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interrupt_signal() {
  return received.load(std::memory_order_relaxed);
}

void register_temporary(const std::filesystem::path& file) {
  const std::string& s = file.native();
  if (s.size() >= sizeof(Slot::path)) return;
  for (Slot& slot : slots) {
    if (slot.used.load()) continue;
    std::memcpy(slot.path, s.c_str(), s.size() + 1);
    slot.used.store(true);  // after the path is complete: the handler never sees half a name
    return;
  }
}

void unregister_temporary(const std::filesystem::path& file) {
  for (Slot& slot : slots)
    if (slot.used.load() && file.native() == slot.path) {
      slot.used.store(false);
      return;
    }
}

}  // namespace scantrace
