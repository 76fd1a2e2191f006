#pragma once
// The streaming sink: one JSON object per line, header first, footer last (design.md §5). Lines
// are flushed at the end of every triangle, so a trace cut short by a crash is readable up to the
// last finished triangle, and its missing footer says that it is incomplete.
#include <filesystem>
#include <memory>
#include <ostream>

#include "events.hpp"
#include "io/atomic_write.hpp"

namespace scantrace::trace {

// Writes to a stream the caller owns.
class JsonlWriter {
 public:
  JsonlWriter(std::ostream& out, const Header& header);
  void write(const Event& e);
  void finish(const Footer& footer);

 private:
  std::ostream* out_;
};

// Writes to a file that appears under its name only when finish() has written the footer.
class JsonlFileWriter {
 public:
  JsonlFileWriter(const std::filesystem::path& path, const Header& header);
  void write(const Event& e) { writer_.write(e); }
  void finish(const Footer& footer);

 private:
  std::unique_ptr<AtomicFile> file_;  // stable address for writer_'s stream
  JsonlWriter writer_;
};

}  // namespace scantrace::trace
