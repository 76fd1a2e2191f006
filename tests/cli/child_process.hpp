#pragma once
// Running scantrace as a child process that a test interrupts. Tests must not depend on the
// machine being quiet: they wait for a condition that says the run has reached the point to be
// interrupted (a file with content, the signal handler installed), by the clock with a generous
// deadline, and they notice a child that ended early instead of waiting the deadline out.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace scantrace::test {

// Starts scantrace in `cwd` with `args` (stdout and stderr to .stdout.txt / .stderr.txt there).
inline pid_t spawn_scantrace(const std::filesystem::path& cwd,
                             const std::vector<std::string>& args) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(cwd.c_str()) != 0) ::_exit(127);
    const int out = ::open(".stdout.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(".stderr.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, 1);
    ::dup2(err, 2);
    std::vector<char*> argv{const_cast<char*>(SCANTRACE_BINARY)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(SCANTRACE_BINARY, argv.data());
    ::_exit(127);
  }
  return pid;
}

// Exit status of a finished child: its code, or 1000 + the signal that killed it.
inline int decode_status(int status) {
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

// A child under test: waits for conditions while it runs, and reaps it exactly once.
class Child {
 public:
  explicit Child(pid_t pid) : pid_(pid) {}
  ~Child() {
    if (!status_) {  // a failed REQUIRE left it running: do not leave it behind
      ::kill(pid_, SIGKILL);
      wait();
    }
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  pid_t pid() const { return pid_; }

  // Polls `ready` until it holds (true), or the child has ended or the deadline passed (false).
  // Five minutes: a loaded shared machine or a sanitizer build is slow to get anywhere, and a
  // quiet one returns as soon as the condition holds.
  bool wait_until(const std::function<bool()>& ready,
                  std::chrono::seconds deadline = std::chrono::seconds(300)) {
    const auto end = std::chrono::steady_clock::now() + deadline;
    while (std::chrono::steady_clock::now() < end) {
      if (ready()) return true;
      if (ended()) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
  }

  // True once the child has exited (reaping it).
  bool ended() {
    if (status_) return true;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) status_ = decode_status(status);
    return status_.has_value();
  }

  // Waits for the child to end; its exit status (see decode_status).
  int wait() {
    if (!status_) {
      int status = 0;
      ::waitpid(pid_, &status, 0);
      status_ = decode_status(status);
    }
    return *status_;
  }

  void signal(int sig) const { ::kill(pid_, sig); }

 private:
  pid_t pid_;
  std::optional<int> status_;
};

// True when `file` exists and is not empty.
inline bool has_content(const std::filesystem::path& file) {
  std::error_code ec;
  return std::filesystem::exists(file, ec) && std::filesystem::file_size(file, ec) > 0 && !ec;
}

// True when process `pid` runs scantrace (it has exec'd: before, the forked child still has the
// test's own handlers) and catches `sig` (its SigCgt mask in /proc): scantrace installs its
// handlers first thing, so from then on a signal is handled, not fatal.
inline bool catches_signal(pid_t pid, int sig) {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/" + std::to_string(pid) + "/exe", ec);
  if (ec || !std::filesystem::equivalent(exe, SCANTRACE_BINARY, ec) || ec) return false;
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("SigCgt:", 0) == 0)
      return (std::stoull(line.substr(7), nullptr, 16) >> (sig - 1)) & 1ULL;
  return false;
}

// The temporary name io/atomic_write.hpp gives `name` in a process `pid`.
inline std::string temporary(const std::string& name, pid_t pid) {
  return "." + name + ".tmp-" + std::to_string(pid);
}

}  // namespace scantrace::test
