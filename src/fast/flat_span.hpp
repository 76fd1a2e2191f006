#pragma once
// Writing one colour over a run of pixels: the one flat span fill of the project (the fills, the
// image canvas and the Python array canvas all come here).
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <vector>

namespace scantrace {

// Spans up to this many pixels are a plain store loop: most spans of a real scene are this short,
// and a call to memcpy costs more than it saves on them.
inline constexpr std::ptrdiff_t kShortSpan = 32;

// Pixels [first, last) := value for a span of at most 8 pixels, without a loop: four stores at
// both ends cover any length from 1 to 4 (0, n−1, n/2 and (n−1)/2 are inside the span and
// between them every pixel), eight any length from 4 to 8. The length of a small triangle's
// spans changes from row to row, so a store loop's exit is mispredicted on a large share of
// rows, and a misprediction costs more than the few stores written twice here (docs/performance.md, "Why the fast code looks as it does"). False, writing nothing, for a longer span.
template <class P>
[[gnu::always_inline]] inline bool fill_few(P* first, P* last, P value) {
  const std::ptrdiff_t n = last - first;
  if (n <= 4) {
    if (n <= 0) return true;  // nothing to write
    first[0] = value, first[n - 1] = value, first[n >> 1] = value, first[(n - 1) >> 1] = value;
    return true;
  }
  if (n > 8) return false;
  first[0] = value, first[1] = value, first[2] = value, first[3] = value;
  last[-4] = value, last[-3] = value, last[-2] = value, last[-1] = value;
  return true;
}

// Pixels [first, last) := value. The value is a local copy on purpose: std::fill reads it through
// a reference, and with 8-bit pixels every byte stored may alias it, so it would be reloaded for
// every pixel. Long spans are a few pixels copied onto the rest in doubling blocks: memcpy moves a
// 3-byte pattern many bytes at a time, a pixel loop three. (Not as fast as memset moves a 1-byte
// one, which on this machine writes a large image twice as fast: docs/performance.md, "The
// clear"; stores of the pattern from registers were tried there and lost in a triangle's spans.)
template <class P>
void fill_pixels(P* first, P* last, P value) {
  if (fill_few(first, last, value)) return;
  if (last - first <= kShortSpan) {
    for (; first != last; ++first) *first = value;
    return;
  }
  for (P* p = first; p != first + kShortSpan; ++p) *p = value;
  for (std::ptrdiff_t done = kShortSpan, n = last - first; done < n;) {
    const std::ptrdiff_t chunk = std::min(done, n - done);
    std::memcpy(first + done, first, static_cast<std::size_t>(chunk) * sizeof(P));
    done += chunk;
  }
}

// A row of one pixel value kept between the spans of a polygon, so that each long span of a large
// flat polygon is a single memcpy from it, where fill_pixels's doubling blocks cost a dozen short
// copies per span. The row grows geometrically to the longest span seen (so building it costs at
// most twice the pixels written), is rebuilt from its first pixel when the value changes, and
// keeps its memory, so a renderer holding one (in FillScratch) allocates nothing per polygon once
// it has grown.
class FlatRow {
 public:
  template <class P>
  void fill(P* first, P* last, P value) {
    static_assert(std::is_trivially_copyable_v<P>);
    if (fill_few(first, last, value)) return;
    const std::ptrdiff_t n = last - first;
    // fill_pixels's store loop, written out again: called from here it is not inlined.
    if (n <= kShortSpan) {
      for (; first != last; ++first) *first = value;
      return;
    }
    if (pixel_size_ != sizeof(P) || std::memcmp(bytes_.data(), &value, sizeof(P)) != 0) {
      pixel_size_ = sizeof(P);
      if (bytes_.size() < sizeof(P)) bytes_.resize(sizeof(P));
      std::memcpy(bytes_.data(), &value, sizeof(P));
      valid_ = 1;
    }
    const auto need = static_cast<std::size_t>(n);
    if (valid_ < need) grow(std::max(need, 2 * valid_));
    std::memcpy(first, bytes_.data(), need * sizeof(P));
  }

 private:
  // Extends the valid pixels to `pixels` by copying the valid part onto the rest, doubling.
  void grow(std::size_t pixels) {
    if (bytes_.size() < pixels * pixel_size_) bytes_.resize(pixels * pixel_size_);
    while (valid_ < pixels) {
      const std::size_t chunk = std::min(valid_, pixels - valid_);
      std::memcpy(bytes_.data() + valid_ * pixel_size_, bytes_.data(), chunk * pixel_size_);
      valid_ += chunk;
    }
  }

  std::vector<unsigned char> bytes_;  // valid_ pixels of pixel_size_ bytes, all equal
  std::size_t pixel_size_ = 0, valid_ = 0;
};

}  // namespace scantrace
