#include "jsonl_writer.hpp"

#include <stdexcept>
#include <variant>

#include "event_json.hpp"

namespace scantrace::trace {

JsonlWriter::JsonlWriter(std::ostream& out, const Header& header) : out_(&out) {
  write(header);
}

void JsonlWriter::write(const Event& e) {
  *out_ << event_to_json(e).dump() << '\n';
  if (std::holds_alternative<TriangleEnd>(e) || std::holds_alternative<TriangleSkipped>(e))
    out_->flush();
}

void JsonlWriter::finish(const Footer& footer) {
  write(footer);
  out_->flush();
  if (!*out_) throw std::runtime_error("trace: write failed");
}

JsonlFileWriter::JsonlFileWriter(const std::filesystem::path& path, const Header& header)
    : file_(std::make_unique<AtomicFile>(path)), writer_(file_->stream(), header) {}

void JsonlFileWriter::finish(const Footer& footer) {
  writer_.finish(footer);
  file_->commit();
}

}  // namespace scantrace::trace
