#include "io/gzip.hpp"

#include <libdeflate.h>

#include <memory>
#include <stdexcept>

namespace scantrace {

std::vector<unsigned char> gzip(std::string_view bytes, int level) {
  const std::unique_ptr<libdeflate_compressor, void (*)(libdeflate_compressor*)> c(
      libdeflate_alloc_compressor(level), &libdeflate_free_compressor);
  if (!c) throw std::runtime_error("out of memory");
  std::vector<unsigned char> out(libdeflate_gzip_compress_bound(c.get(), bytes.size()));
  const std::size_t n =
      libdeflate_gzip_compress(c.get(), bytes.data(), bytes.size(), out.data(), out.size());
  // The bound is libdeflate's own worst case: a shortfall is a bug, not an input.
  if (n == 0) throw std::logic_error("gzip: the compressed data did not fit its bound");
  out.resize(n);
  return out;
}

}  // namespace scantrace
