#include "jsonl_writer.hpp"

#include <stdexcept>
#include <variant>

#include "event_json.hpp"
#include "io/interrupt.hpp"

namespace scantrace::trace {

JsonlWriter::JsonlWriter(std::ostream& out, const Header& header) : out_(&out) {
  write(header);
}

namespace {

bool ends_triangle(const Event& e) {
  return std::holds_alternative<TriangleEnd>(e) || std::holds_alternative<TriangleSkipped>(e);
}

}  // namespace

void JsonlWriter::write_line(const std::string& line, bool flush) {
  *out_ << line << '\n';
  bytes_ += static_cast<std::int64_t>(line.size()) + 1;
  if (flush) out_->flush();
}

void JsonlWriter::write(const Event& e) {
  write_line(event_to_json(e).dump(), ends_triangle(e));
}

bool JsonlWriter::write_within(const Event& e, std::int64_t max_bytes) {
  const std::string line = event_to_json(e).dump();
  if (bytes_ + static_cast<std::int64_t>(line.size()) + 1 > max_bytes) return false;
  write_line(line, ends_triangle(e));
  return true;
}

void JsonlWriter::finish(const Footer& footer) {
  write(footer);
  out_->flush();
  if (!*out_) throw std::runtime_error("trace: write failed");
}

JsonlFileWriter::JsonlFileWriter(const std::filesystem::path& path, const Header& header)
    : file_(std::make_unique<AtomicFile>(path)), writer_(file_->stream(), header) {}

void JsonlFileWriter::write(const Event& e) {
  check_interrupt();
  writer_.write(e);
}

bool JsonlFileWriter::write_within(const Event& e, std::int64_t max_bytes) {
  check_interrupt();
  return writer_.write_within(e, max_bytes);
}

void JsonlFileWriter::finish(const Footer& footer) {
  writer_.finish(footer);
  file_->commit();
}

}  // namespace scantrace::trace
