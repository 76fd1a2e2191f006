#pragma once
// A large allocation is checked against the memory there is before it is made, so that a canvas
// too large for the machine is a clear message naming the input, not an out-of-memory kill.
#include <cstdint>
#include <new>
#include <optional>
#include <string>

namespace scantrace {

// Bytes this process can still allocate without swapping: MemAvailable of /proc/meminfo, lowered
// to the remaining allowance of its cgroup and every ancestor's (memory.max − memory.current)
// where one is set, to what RLIMIT_AS and RLIMIT_DATA leave (the limit less the process's virtual
// and data size), and to the environment's SCANTRACE_MAX_MEMORY ("512M", "2G", bytes) when given.
// nullopt where none is known (then nothing is refused).
std::optional<std::uint64_t> available_memory();

// Throws InputError(file, element, "<what> needs about X GiB, more than the Y GiB available")
// when `bytes` exceeds available_memory().
void check_memory(std::uint64_t bytes, const std::string& what, const std::string& file,
                  const std::string& element);

// The problem said when an allocation fails anyway (a budget estimate that fell short, memory
// taken by another process meanwhile): "ran out of memory while reading it (... available)".
std::string out_of_memory_problem();

[[noreturn]] void throw_out_of_memory(const std::string& file);

// Runs `read` (a reader of `file`), turning std::bad_alloc into the usual one line naming the
// file: InputError(file, "", out_of_memory_problem()).
template <class Read>
auto within_memory(const std::string& file, Read&& read) -> decltype(read()) {
  try {
    return read();
  } catch (const std::bad_alloc&) {
    throw_out_of_memory(file);
  }
}
// "3.2 GiB", "512 MiB": for messages.
std::string format_bytes(std::uint64_t bytes);

}  // namespace scantrace
