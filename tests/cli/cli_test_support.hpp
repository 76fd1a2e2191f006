#pragma once
// Helpers of the tests in tests/cli: scratch directories, small files, and running the scantrace
// binary as a user would, through the shell.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace scantrace::test {

// A fresh directory under the system temp dir, removed with everything in it at scope exit.
// Named by pid and a counter: CTest runs test cases as parallel processes.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("scantrace-cli-tests-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Single-quoted for the POSIX shell.
inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

// Runs the scantrace binary with `args` in the directory `cwd`, capturing stdout and stderr.
// With `timeout_seconds`, a run that has not ended by then is killed (SIGKILL: exit code 137), so
// that a regression to a hang fails the test instead of hanging it.
inline RunResult run_scantrace(const std::filesystem::path& cwd,
                               const std::vector<std::string>& args, int timeout_seconds = 0) {
  const std::filesystem::path out = cwd / ".stdout.txt", err = cwd / ".stderr.txt";
  // Built by appending: GCC 12 raises a false -Wrestrict alarm on "literal" + std::string&&.
  std::string command = "cd ";
  command += shell_quote(cwd.string());
  command += " && ";
  if (timeout_seconds > 0) {
    command += "timeout -s KILL ";
    command += std::to_string(timeout_seconds);
    command += ' ';
  }
  command += shell_quote(SCANTRACE_BINARY);
  for (const std::string& a : args) {
    command += ' ';
    command += shell_quote(a);
  }
  command += " >";
  command += shell_quote(out.string());
  command += " 2>";
  command += shell_quote(err.string());
  const int status = std::system(command.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

// The files of `dir`, by name (the captured output files of run_scantrace excluded).
inline std::vector<std::string> file_names(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name != ".stdout.txt" && name != ".stderr.txt") names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

inline std::filesystem::path shared_data(const std::string& name) {
  return std::filesystem::path(SCANTRACE_SHARED_DATA) / name;
}

}  // namespace scantrace::test
