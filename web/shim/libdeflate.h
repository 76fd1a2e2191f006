#pragma once
// The four libdeflate calls io/png_writer.cpp makes, for the WebAssembly build (web/), where
// Debian's libdeflate (compiled for the host) cannot be linked. The zlib stream is made of stored
// (uncompressed) deflate blocks: a valid PNG, larger than libdeflate's, decoded the same. The
// module's PNGs are the pixel blocks of canvas frames, decoded at once by the page, never files.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

struct libdeflate_compressor {};

inline libdeflate_compressor* libdeflate_alloc_compressor(int) { return new libdeflate_compressor; }
inline void libdeflate_free_compressor(libdeflate_compressor* c) { delete c; }

// 2 bytes of zlib header, 5 per stored block of at most 65535 bytes, 4 of Adler-32.
inline std::size_t libdeflate_zlib_compress_bound(libdeflate_compressor*, std::size_t n) {
  return 2 + 5 * (n / 65535 + 1) + n + 4;
}

inline std::size_t libdeflate_zlib_compress(libdeflate_compressor*, const void* in, std::size_t n,
                                            void* out, std::size_t avail) {
  if (avail < libdeflate_zlib_compress_bound(nullptr, n)) return 0;
  const auto* src = static_cast<const std::uint8_t*>(in);
  auto* dst = static_cast<std::uint8_t*>(out);
  std::size_t o = 0;
  dst[o++] = 0x78;  // deflate, 32 KB window
  dst[o++] = 0x01;  // no dictionary, fastest; (0x78 << 8 | 0x01) % 31 == 0
  std::size_t at = 0;
  do {
    const std::size_t len = n - at < 65535 ? n - at : 65535;
    dst[o++] = at + len == n ? 1 : 0;  // BFINAL, BTYPE 00 (stored)
    dst[o++] = static_cast<std::uint8_t>(len);
    dst[o++] = static_cast<std::uint8_t>(len >> 8);
    dst[o++] = static_cast<std::uint8_t>(~len);
    dst[o++] = static_cast<std::uint8_t>(~len >> 8);
    std::memcpy(dst + o, src + at, len);
    o += len;
    at += len;
  } while (at < n);
  std::uint32_t a = 1, b = 0;
  for (std::size_t i = 0; i < n; ++i) {
    a = (a + src[i]) % 65521;
    b = (b + a) % 65521;
  }
  const std::uint32_t adler = b << 16 | a;
  for (int s = 24; s >= 0; s -= 8) dst[o++] = static_cast<std::uint8_t>(adler >> s);
  return o;
}

// CRC-32 (PNG's, reflected 0xEDB88320), a byte at a time from a table: a frame's pixel block is a
// megabyte, and the bit-at-a-time loop took a tenth of a second of it in the page.
inline std::uint32_t libdeflate_crc32(std::uint32_t crc, const void* data, std::size_t n) {
  static const auto table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
      t[i] = c;
    }
    return t;
  }();
  const auto* p = static_cast<const std::uint8_t*>(data);
  crc = ~crc;
  for (std::size_t i = 0; i < n; ++i) crc = table[(crc ^ p[i]) & 0xFFu] ^ (crc >> 8);
  return ~crc;
}
