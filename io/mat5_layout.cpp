#include "io/mat5_layout.hpp"

#include <zlib.h>

#include <cstdint>
#include <algorithm>

#include "io/interrupt.hpp"

namespace scantrace {
namespace {

// Data types and array classes of the MAT-file format (MathWorks, "MAT-File Format", R2021).
enum : std::uint32_t {
  miINT8 = 1, miUINT8, miINT16, miUINT16, miINT32, miUINT32, miSINGLE,
  miDOUBLE = 9, miINT64 = 12, miUINT64, miMATRIX, miCOMPRESSED, miUTF8, miUTF16, miUTF32
};
constexpr std::uint32_t kFirstNumericClass = 6, kLastNumericClass = 15;  // mxDOUBLE..mxUINT64

std::size_t type_size(std::uint32_t type) {
  switch (type) {
    case miINT8: case miUINT8: case miUTF8: return 1;
    case miINT16: case miUINT16: case miUTF16: return 2;
    case miINT32: case miUINT32: case miSINGLE: case miUTF32: return 4;
    case miDOUBLE: case miINT64: case miUINT64: return 8;
    default: return 0;
  }
}

// Reads the file's integers in its byte order ("IM" at byte 126: little-endian, "MI": big).
class Bytes {
 public:
  Bytes(std::string_view b, bool big_endian) : b_(b), big_(big_endian) {}
  std::size_t size() const { return b_.size(); }
  // 0 past the end: a compressed element's tags are read from its inflated head only, and a tag
  // that lies beyond it (a rank in the hundreds) reads as damaged instead of out of bounds.
  std::uint32_t u32(std::size_t at) const {
    if (at + 4 > b_.size()) return 0;
    std::uint32_t v = 0;
    for (int k = 0; k < 4; ++k) {
      const auto byte = static_cast<unsigned char>(b_[at + (big_ ? k : 3 - k)]);
      v = v << 8 | byte;
    }
    return v;
  }
  std::string_view view(std::size_t at, std::size_t n) const {
    return at < b_.size() ? b_.substr(at, n) : std::string_view();
  }

 private:
  std::string_view b_;
  bool big_;
};

// One data element's tag: the full form (type, byte count) or the small form (both in the first
// four bytes, the data in the next four).
struct Tag {
  std::uint32_t type = 0;
  std::uint64_t bytes = 0, data = 0, next = 0;  // offsets of the data and of the next element
};

std::optional<Tag> tag_at(const Bytes& b, std::uint64_t at, std::uint64_t end) {
  if (at + 8 > end || at + 8 > b.size()) return std::nullopt;
  const std::uint32_t first = b.u32(at);
  Tag t;
  if (first >> 16) {  // small data element
    t.type = first & 0xFFFF, t.bytes = first >> 16, t.data = at + 4, t.next = at + 8;
    if (t.bytes > 4) return std::nullopt;
    return t;
  }
  t.type = first, t.bytes = b.u32(at + 4), t.data = at + 8;
  t.next = t.data + ((t.bytes + 7) / 8) * 8;  // sub-elements are padded to 8 bytes
  if (t.data + t.bytes > end) return std::nullopt;
  return t;
}

std::string count_text(std::uint64_t n) { return std::to_string(n); }

// The sub-elements of one miMATRIX whose data lies in [at, end) of `b`: array flags, dimensions,
// name, then (numeric classes) the real part, whose element count must match the dimensions.
std::optional<Mat5Problem> matrix_problem(const Bytes& b, std::uint64_t at, std::uint64_t end) {
  const auto damaged = [](std::string element, std::string what) {
    return Mat5Problem{std::move(element), "the file is damaged: " + std::move(what)};
  };
  if (at == end) return std::nullopt;  // an empty element (MATLAB writes them for [])
  const auto flags = tag_at(b, at, end);
  if (!flags || flags->bytes < 8) return damaged("", "a variable's array flags are cut short");
  const std::uint32_t cls = b.u32(flags->data) & 0xFF;
  const auto dims = tag_at(b, flags->next, end);
  if (!dims || dims->type != miINT32 || dims->bytes % 4 != 0 || dims->bytes == 0)
    return damaged("", "a variable's dimensions are cut short");
  std::uint64_t declared = 1;
  bool overflow = false;
  std::string shape;
  for (std::uint64_t k = 0; k < dims->bytes / 4; ++k) {
    const std::uint64_t d = b.u32(dims->data + 4 * k);
    if (k) shape += 'x';  // appended apart: GCC 12 warns falsely on "literal" + std::string&&
    shape += count_text(d);
    if (d != 0 && declared > (std::uint64_t{1} << 62) / d) overflow = true;
    declared *= d;
  }
  const auto name = tag_at(b, dims->next, end);
  if (!name) return damaged("", "a variable's name is cut short");
  const std::string var(b.view(name->data, name->bytes));
  if (cls < kFirstNumericClass || cls > kLastNumericClass) return std::nullopt;  // matio decides
  const auto real = tag_at(b, name->next, end);
  if (!real || type_size(real->type) == 0)
    return damaged(var, "its values are missing or cut short (dimensions " + shape + ")");
  const std::uint64_t held = real->bytes / type_size(real->type);
  if (overflow || held != declared || real->bytes % type_size(real->type) != 0)
    return damaged(var, "its dimensions " + shape + " declare " +
                            (overflow ? std::string("more") : count_text(declared)) +
                            " values but its data holds " + count_text(held));
  return std::nullopt;
}

// Inflates a compressed element in a fixed buffer, keeping its first kKept bytes (the tag and
// the sub-elements up to the real part's tag) and counting the rest. Returns false on a zlib
// error or a stream that ends before its end marker.
constexpr std::size_t kKept = 4096;
bool inflate_head(std::string_view in, std::string& head, std::uint64_t& total) {
  z_stream z{};
  if (inflateInit(&z) != Z_OK) return false;
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = static_cast<uInt>(in.size());
  unsigned char buffer[1 << 16];
  int status = Z_OK;
  total = 0;
  std::size_t rounds = 0;
  while (status == Z_OK) {
    z.next_out = buffer, z.avail_out = sizeof buffer;
    status = inflate(&z, Z_NO_FLUSH);
    const std::size_t produced = sizeof buffer - z.avail_out;
    if (head.size() < kKept)
      head.append(reinterpret_cast<char*>(buffer), std::min(produced, kKept - head.size()));
    total += produced;
    if (status == Z_BUF_ERROR && z.avail_in == 0) break;  // input ended without the end marker
    if ((++rounds & 255) == 0) check_interrupt();  // a bomb inflates ~1000:1: keep SIGTERM alive
  }
  inflateEnd(&z);
  return status == Z_STREAM_END;
}

std::optional<Mat5Problem> compressed_problem(const Bytes& b, const Tag& t, bool big_endian) {
  std::string head;
  std::uint64_t total = 0;
  if (!inflate_head(b.view(t.data, t.bytes), head, total))
    return Mat5Problem{"", "the file is damaged: a compressed variable does not inflate whole"};
  const Bytes inner(head, big_endian);
  if (head.size() < 8 || inner.u32(0) != miMATRIX)
    return Mat5Problem{"", "the file is damaged: a compressed variable holds no matrix"};
  const std::uint64_t declared = inner.u32(4);
  if (8 + declared > total)
    return Mat5Problem{"", "the file is damaged: a compressed variable inflates to " +
                               count_text(total) + " bytes, its matrix declares " +
                               count_text(8 + declared)};
  // The tags are read from the kept head (the real part's tag comes after the flags, up to 8·rank
  // bytes of dimensions and the name); the element's end is where it declares, which the
  // inflated total reaches, so a real part's byte count is checked against it.
  return matrix_problem(inner, 8, 8 + declared);
}

}  // namespace

MatFileVersion mat_file_version(std::string_view file) {
  if (file.size() < 128) return MatFileVersion::other;
  const std::string_view endian = file.substr(126, 2);
  if (endian != "IM" && endian != "MI") return MatFileVersion::other;
  const bool big = endian == "MI";
  const auto version = static_cast<unsigned>(static_cast<unsigned char>(file[big ? 124 : 125]))
                           << 8 |
                       static_cast<unsigned char>(file[big ? 125 : 124]);
  // matio decides between its v5 and HDF5 readers on the same two bytes, read the same way.
  if (version == 0x0100) return MatFileVersion::v5;
  if (version == 0x0200) return MatFileVersion::v73;
  return MatFileVersion::other;
}

std::optional<Mat5Problem> mat5_layout_problem(std::string_view file) {
  if (mat_file_version(file) != MatFileVersion::v5) return std::nullopt;
  const bool big = file.substr(126, 2) == "MI";
  const Bytes b(file, big);
  std::size_t at = 128;
  while (at + 8 <= b.size()) {
    const std::uint32_t type = b.u32(at);
    const std::uint64_t bytes = b.u32(at + 4);
    if (at + 8 + bytes > b.size())
      return Mat5Problem{"", "the file is truncated: a variable declares " + count_text(bytes) +
                                 " bytes, the file ends " + count_text(b.size() - at - 8) +
                                 " bytes after its tag"};
    const Tag t{type, bytes, at + 8, at + 8 + bytes};
    std::optional<Mat5Problem> p;
    if (type == miMATRIX)
      p = matrix_problem(b, t.data, t.data + bytes);
    else if (type == miCOMPRESSED)
      p = compressed_problem(b, t, big);
    if (p) return p;
    at = t.next;
  }
  return std::nullopt;
}

}  // namespace scantrace
