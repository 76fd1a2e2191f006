#pragma once
// Writing one colour over a run of pixels: the one flat span fill of the project (the fills, the
// image canvas and the Python array canvas all come here).
#include <algorithm>
#include <cstddef>
#include <cstring>

namespace scantrace {

// Pixels [first, last) := value. The value is a local copy on purpose: std::fill reads it through
// a reference, and with 8-bit pixels every byte stored may alias it, so it would be reloaded for
// every pixel. Short spans (the common case) are a plain loop; long ones are a few pixels copied
// onto the rest in doubling blocks: memcpy moves a 3-byte pattern as fast as memset moves a
// 1-byte one, a pixel loop does not.
template <class P>
void fill_pixels(P* first, P* last, P value) {
  constexpr std::ptrdiff_t kShort = 32;
  if (last - first <= kShort) {
    for (; first != last; ++first) *first = value;
    return;
  }
  for (P* p = first; p != first + kShort; ++p) *p = value;
  for (std::ptrdiff_t done = kShort, n = last - first; done < n;) {
    const std::ptrdiff_t chunk = std::min(done, n - done);
    std::memcpy(first + done, first, static_cast<std::size_t>(chunk) * sizeof(P));
    done += chunk;
  }
}

}  // namespace scantrace
