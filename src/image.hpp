#pragma once
// A row-major raster indexed img(x, y) = img[y][x]. The pixel type is a template parameter so that
// the same fill writes the course's float canvas (Rgb32f, colours in [0, 1]) or a coverage-count
// grid in the tests; a pixel type provides `static P from(Color)`.
#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <optional>
#include <span>
#include <type_traits>

#include "color.hpp"

namespace scantrace {

// The course's canvas pixel: three floats in [0, 1], RGB order.
struct Rgb32f {
  float r = 0, g = 0, b = 0;
  static Rgb32f from(Color c) {
    return {static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b)};
  }
  Color color() const { return {r, g, b}; }
  friend constexpr bool operator==(Rgb32f, Rgb32f) = default;
};

// round(255·c) clamped to [0, 255] (docs/design.md §2); NaN becomes 0. For 0 < v < 255 the
// truncation i = (int)v is floor(v) and v − i is exact, so the tie test is exact too: no libm call,
// which matters because a Gouraud fill converts every pixel it writes.
inline std::uint8_t to_byte(double c) {
  const double v = 255.0 * c;
  if (!(v > 0.0)) return 0;
  if (v >= 255.0) return 255;
  const int i = static_cast<int>(v);
  return static_cast<std::uint8_t>(i + (v - i >= 0.5 ? 1 : 0));
}

// An 8-bit pixel stored blue, green, red: the layout of OpenCV's CV_8UC3 and of the video and
// image writers, so an Image<Bgr8> is handed to them without a conversion pass. Only the memory
// order differs; the fill still speaks RGB Color.
struct Bgr8 {
  std::uint8_t b = 0, g = 0, r = 0;
  static Bgr8 from(Color c) { return {to_byte(c.b), to_byte(c.g), to_byte(c.r)}; }
  Color color() const { return {r / 255.0, g / 255.0, b / 255.0}; }
  friend constexpr bool operator==(Bgr8, Bgr8) = default;
};
static_assert(sizeof(Bgr8) == 3);

namespace detail {
// Uninitialised storage of `bytes` bytes for an image's pixels, released with std::free; large
// images get huge pages where the system offers them (image.cpp says why). Throws
// std::bad_alloc.
void* allocate_pixels(std::size_t bytes);
}  // namespace detail

template <class P>
class Image {
  static_assert(std::is_trivially_copyable_v<P>);

 public:
  using Pixel = P;

  Image() = default;
  Image(int width, int height, P fill = P{})
      : width_(width),
        height_(height),
        size_(static_cast<std::size_t>(width) * height),
        pixels_(allocate(size_)) {
    fill_all(fill);
  }
  Image(const Image& o) : Image(o.width_, o.height_, P{}) {
    if (size_) std::memcpy(pixels_.get(), o.pixels_.get(), size_ * sizeof(P));
  }
  Image(Image&&) noexcept = default;
  Image& operator=(const Image& o) { return *this = Image(o); }
  Image& operator=(Image&&) noexcept = default;

  int width() const { return width_; }
  int height() const { return height_; }

  P& operator()(int x, int y) {
    assert(x >= 0 && x < width_ && y >= 0 && y < height_);
    return pixels_[static_cast<std::size_t>(y) * width_ + x];
  }
  const P& operator()(int x, int y) const {
    assert(x >= 0 && x < width_ && y >= 0 && y < height_);
    return pixels_[static_cast<std::size_t>(y) * width_ + x];
  }
  P* row(int y) { return pixels_.get() + static_cast<std::size_t>(y) * width_; }
  const P* row(int y) const { return pixels_.get() + static_cast<std::size_t>(y) * width_; }
  std::span<const P> pixels() const { return {pixels_.get(), size_}; }

  // Makes this a width × height image of `fill`, keeping the storage when the pixel count is
  // unchanged: a caller that renders again into the same image pays neither the allocation nor
  // the first-touch page faults of a fresh one (for a 4096² 8-bit image those cost several times
  // the clear itself).
  void reset(int width, int height, P fill) {
    reshape(width, height);
    fill_all(fill);
  }
  // The same without the clear: the pixels are left as they are (or unwritten, when the storage
  // is new), for a caller that writes every pixel itself (the near-to-far render, painter.hpp).
  void reshape(int width, int height) {
    const std::size_t size = static_cast<std::size_t>(width) * height;
    if (size != size_ || !pixels_) pixels_ = allocate(size);
    width_ = width;
    height_ = height;
    size_ = size;
  }

  // Sets every pixel to `value`. Clearing is part of every render. A pixel of one repeated byte
  // (white and black 8-bit pixels: what renders clear to by default) is a memset, which glibc
  // writes with `rep stosb`; an image larger than the caches is cleared twice as fast that way as
  // by the copies below (a 4096² 8-bit clear: 1.7-1.8 ms against 3.0-3.4 ms; docs/performance.md,
  // "The clear"), since ordinary stores first fetch each line they overwrite.
  //
  // Any other pixel is written, and copied onto the rest of a block in doubling steps, and that
  // block is copied over the image. The block is small enough to stay in the L1 cache; doubling
  // over the whole image would read its first half back from memory to write the second. Glibc's
  // copy beats stores of the pattern from SSE registers at the sizes scenes have
  // (docs/performance.md, "Why the fast code looks as it does").
  void fill_all(P value) {
    if (size_ == 0) return;
    if (const auto byte = repeated_byte(value)) {
      std::memset(static_cast<void*>(pixels_.get()), *byte, size_ * sizeof(P));
      return;
    }
    constexpr std::size_t kBlock = std::max<std::size_t>(1, 8192 / sizeof(P));
    const std::size_t block = std::min(kBlock, size_);
    P* const p = pixels_.get();
    p[0] = value;
    for (std::size_t done = 1; done < block;) {
      const std::size_t n = std::min(done, block - done);
      std::memcpy(p + done, p, n * sizeof(P));
      done += n;
    }
    for (std::size_t done = block; done < size_;) {
      const std::size_t n = std::min(block, size_ - done);
      std::memcpy(p + done, p, n * sizeof(P));
      done += n;
    }
  }

  friend bool operator==(const Image& a, const Image& b) {
    return a.width_ == b.width_ && a.height_ == b.height_ &&
           std::equal(a.pixels_.get(), a.pixels_.get() + a.size_, b.pixels_.get());
  }

 private:
  // The byte that every byte of `value` is, if there is one (never for a type with padding or
  // with several representations of a value, such as float's ±0).
  static std::optional<unsigned char> repeated_byte(const P& value) {
    if constexpr (std::has_unique_object_representations_v<P>) {
      unsigned char bytes[sizeof(P)];
      std::memcpy(bytes, &value, sizeof(P));
      if (std::all_of(bytes, bytes + sizeof(P), [&](unsigned char b) { return b == bytes[0]; }))
        return bytes[0];
    }
    return std::nullopt;
  }

  // Raw storage: the clear writes every pixel anyway, so constructing them first would be a
  // second pass over the image. Pixel types are aggregates of numbers (implicit-lifetime types),
  // which live in such storage once written.
  struct Release {
    void operator()(P* p) const { std::free(p); }
  };
  static std::unique_ptr<P[], Release> allocate(std::size_t n) {
    return std::unique_ptr<P[], Release>(static_cast<P*>(detail::allocate_pixels(n * sizeof(P))));
  }

  int width_ = 0, height_ = 0;
  std::size_t size_ = 0;
  std::unique_ptr<P[], Release> pixels_;
};

using RgbImage = Image<Rgb32f>;
using Bgr8Image = Image<Bgr8>;

}  // namespace scantrace
