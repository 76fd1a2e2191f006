#include "io/memory_budget.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

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

}  // namespace

std::optional<std::uint64_t> available_memory() {
  std::optional<std::uint64_t> available = meminfo_available();
  if (const auto budget = user_budget())
    available = available ? std::min(*available, *budget) : *budget;
  const auto max = read_number("/sys/fs/cgroup/memory.max");
  const auto current = read_number("/sys/fs/cgroup/memory.current");
  if (max && current) {
    const std::uint64_t left = *max > *current ? *max - *current : 0;
    available = available ? std::min(*available, left) : left;
  }
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
                       " of memory available (SCANTRACE_MAX_MEMORY or the system)");
}

}  // namespace scantrace
