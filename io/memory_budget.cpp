#include "io/memory_budget.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

#include "io/input_error.hpp"

namespace scantrace {
namespace {

std::optional<std::uint64_t> meminfo_available() {
  std::ifstream in("/proc/meminfo");
  for (std::string key; in >> key;) {
    std::uint64_t kib = 0;
    std::string unit;
    in >> kib >> unit;
    if (key == "MemAvailable:") return kib * 1024;
  }
  return std::nullopt;
}

std::optional<std::uint64_t> read_number(const char* file) {
  std::ifstream in(file);
  std::uint64_t v = 0;
  if (in >> v) return v;
  return std::nullopt;  // absent, or "max"
}

// SCANTRACE_MAX_MEMORY: "512M", "2G" or a number of bytes; anything else is ignored.
std::optional<std::uint64_t> user_budget() {
  const char* text = std::getenv("SCANTRACE_MAX_MEMORY");
  if (!text || !*text) return std::nullopt;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(text, &end, 10);
  const std::string unit = end;
  const int shift = unit.empty() ? 0 : unit == "K" ? 10 : unit == "M" ? 20 : unit == "G" ? 30 : -1;
  if (end == text || shift < 0 || v > (UINT64_MAX >> shift)) return std::nullopt;
  return static_cast<std::uint64_t>(v) << shift;
}

// The cgroup (v2) this process is in: "0::/user.slice/..." in /proc/self/cgroup; its limits are
// under /sys/fs/cgroup/<that path>. Each ancestor's memory.max bounds it too.
std::optional<std::uint64_t> cgroup_left() {
  std::ifstream in("/proc/self/cgroup");
  std::string line, path;
  while (std::getline(in, line))
    if (line.rfind("0::", 0) == 0) path = line.substr(3);
  std::optional<std::uint64_t> left;
  for (std::string dir = path;; dir = dir.substr(0, dir.rfind('/'))) {
    const std::string base = "/sys/fs/cgroup" + dir;
    const auto max = read_number((base + "/memory.max").c_str());
    const auto current = read_number((base + "/memory.current").c_str());
    if (max && current) {
      const std::uint64_t here = *max > *current ? *max - *current : 0;
      left = left ? std::min(*left, here) : here;
    }
    if (dir.empty() || dir == "/") break;
  }
  return left;
}

// The address-space and data-segment limits (ulimit -v, ulimit -d; a grader's sandbox sets them)
// less what the process already has: past them malloc fails whatever MemAvailable says.
std::optional<std::uint64_t> rlimit_left() {
  // /proc/self/statm: sizes in pages; the first is the virtual size, the sixth data + stack.
  std::ifstream in("/proc/self/statm");
  std::uint64_t size = 0, resident = 0, shared = 0, text = 0, lib = 0, data = 0;
  in >> size >> resident >> shared >> text >> lib >> data;
  const auto page = static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
  std::optional<std::uint64_t> left;
  const auto limit = [&](int resource, std::uint64_t used) {
    struct rlimit r {};
    if (::getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY || !in) return;
    const std::uint64_t cur = r.rlim_cur, here = cur > used ? cur - used : 0;
    left = left ? std::min(*left, here) : here;
  };
  limit(RLIMIT_AS, size * page);
  limit(RLIMIT_DATA, data * page);
  return left;
}

}  // namespace

std::optional<std::uint64_t> available_memory() {
  std::optional<std::uint64_t> available = meminfo_available();
  for (const auto bound : {user_budget(), cgroup_left(), rlimit_left()})
    if (bound) available = available ? std::min(*available, *bound) : *bound;
  return available;
}

std::string format_bytes(std::uint64_t bytes) {
  char buf[32];
  if (bytes >= (std::uint64_t{1} << 30))
    std::snprintf(buf, sizeof buf, "%.1f GiB", static_cast<double>(bytes) / (1 << 30));
  else
    std::snprintf(buf, sizeof buf, "%.0f MiB", static_cast<double>(bytes) / (1 << 20));
  return buf;
}

void check_memory(std::uint64_t bytes, const std::string& what, const std::string& file,
                  const std::string& element) {
  const auto available = available_memory();
  if (!available || bytes <= *available) return;
  throw InputError(file, element,
                   what + " needs about " + format_bytes(bytes) + ", more than the " +
                       format_bytes(*available) +
                       " of memory available (SCANTRACE_MAX_MEMORY, the system, ulimit -v/-d "
                       "or the cgroup)");
}

std::string out_of_memory_problem() {
  const auto available = available_memory();
  return "ran out of memory while reading it" +
         (available ? " (" + format_bytes(*available) + " available now)" : std::string()) +
         "; SCANTRACE_MAX_MEMORY sets the budget that is checked before large allocations";
}

void throw_out_of_memory(const std::string& file) {
  throw InputError(file, "", out_of_memory_problem());
}

}  // namespace scantrace
