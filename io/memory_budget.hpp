#pragma once
// A large allocation is checked against the memory there is before it is made, so that a canvas
// too large for the machine is a clear message naming the input, not an out-of-memory kill.
#include <cstdint>
#include <optional>
#include <string>

namespace scantrace {

// Bytes this process can still allocate without swapping: MemAvailable of /proc/meminfo, lowered
// to the cgroup's remaining allowance (memory.max − memory.current) when one is set, and to the
// environment's SCANTRACE_MAX_MEMORY ("512M", "2G", bytes) when given. nullopt where none is
// known (then nothing is refused).
std::optional<std::uint64_t> available_memory();

// Throws InputError(file, element, "<what> needs about X GiB, more than the Y GiB available")
// when `bytes` exceeds available_memory().
void check_memory(std::uint64_t bytes, const std::string& what, const std::string& file,
                  const std::string& element);

// "3.2 GiB", "512 MiB": for messages.
std::string format_bytes(std::uint64_t bytes);

}  // namespace scantrace
