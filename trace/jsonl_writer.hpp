#pragma once
// The streaming sink: one JSON object per line, header first, footer last (docs/design.md §5).
// Lines are flushed at the end of every triangle, so a trace cut short by a crash is readable up to
// the last finished triangle, and its missing footer says that it is incomplete.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>

#include "events.hpp"
#include "io/atomic_write.hpp"

namespace scantrace::trace {

// Writes to a stream the caller owns.
class JsonlWriter {
 public:
  JsonlWriter(std::ostream& out, const Header& header);
  void write(const Event& e);
  // Writes `e` only if the bytes written so far and its line stay within `max_bytes`.
  bool write_within(const Event& e, std::int64_t max_bytes);
  void finish(const Footer& footer);
  std::int64_t bytes() const { return bytes_; }

 private:
  void write_line(const std::string& line, bool flush);
  std::ostream* out_;
  std::int64_t bytes_ = 0;
};

// Writes to a file that appears under its name only when finish() has written the footer.
class JsonlFileWriter {
 public:
  JsonlFileWriter(const std::filesystem::path& path, const Header& header);
  // Both check for Ctrl-C (io/interrupt.hpp): writing a large trace is a long loop.
  void write(const Event& e);
  bool write_within(const Event& e, std::int64_t max_bytes);
  void finish(const Footer& footer);

 private:
  std::unique_ptr<AtomicFile> file_;  // stable address for writer_'s stream
  JsonlWriter writer_;
};

}  // namespace scantrace::trace
