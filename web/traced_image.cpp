#include "web/traced_image.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>

#include "src/fast/flat_span.hpp"
#include "web/bindings.hpp"

namespace scantrace::web {
namespace {

struct Rgba8 {
  std::uint8_t r, g, b, a;
};

Rgba8 bytes_of(const Rgb32f& p) { return {to_byte(p.r), to_byte(p.g), to_byte(p.b), 255}; }

// A span put back to the background: a few pixels stored, then copied after themselves in
// doubling blocks. The copies are this file's own (internal linkage, compiled with -mbulk-memory:
// memory.copy, web/CMakeLists.txt): src/fast/flat_span.hpp's fill_pixels does the same, but the linker
// kept src/'s instance of that inline template, whose copies are calls to emscripten's __memcpy, a
// loop in WebAssembly (0.4 ms of a drag's move in Chromium for the course triangle's 35,000
// pixels, twice); a plain store loop was slower still there (0.5 ms).
template <class P>
void put_back(P* first, P* last, P value) {
  const std::ptrdiff_t n = last - first;
  constexpr std::ptrdiff_t kStored = 16;
  for (std::ptrdiff_t i = 0; i < std::min(n, kStored); ++i) first[i] = value;
  for (std::ptrdiff_t done = kStored; done < n;) {
    const std::ptrdiff_t chunk = std::min(done, n - done);
    std::memcpy(first + done, first, static_cast<std::size_t>(chunk) * sizeof(P));
    done += chunk;
  }
}

// Calls put(y, span) for every span of a scanline event of `t` (the inside intervals of a
// polygon's row).
template <class Put>
void for_each_span(const trace::Trace& t, Put&& put) {
  for (const trace::Event& e : t.events())
    if (const auto* row = std::get_if<trace::Scanline>(&e)) {
      if (row->intervals)
        for (const trace::Interval& iv : *row->intervals) put(row->y, iv.pixels);
      else if (row->span)
        put(row->y, *row->span);
    }
}

}  // namespace

RgbImage& TracedImage::canvas_for(int width, int height, const Color& background,
                                  const trace::Trace* last) {
  const Rgb32f bg = Rgb32f::from(background);
  const bool same = canvas_.width() == width && canvas_.height() == height &&
                    std::memcmp(&bg, &background_, sizeof bg) == 0;
  const std::size_t w = static_cast<std::size_t>(width);
  if (spans_only_ && last && same) {
    const Rgba8 bg8 = bytes_of(bg);
    auto* pixels = reinterpret_cast<Rgba8*>(rgba_.data());
    for_each_span(*last, [&](i64 y, const trace::Span& s) {
      Rgb32f* row = canvas_.row(static_cast<int>(y));
      put_back(row + s.x_begin, row + s.x_end, bg);
      Rgba8* out = pixels + static_cast<std::size_t>(y) * w;
      put_back(out + s.x_begin, out + s.x_end, bg8);
    });
  } else {
    canvas_.reset(width, height, bg);
    // The background by fill_pixels (src/fast/flat_span.hpp): a few pixels, then copied onto the rest
    // in doubling blocks, which emscripten hands to the engine's own copy.
    rgba_.resize(w * static_cast<std::size_t>(height) * 4);
    auto* pixels = reinterpret_cast<Rgba8*>(rgba_.data());
    fill_pixels(pixels, pixels + rgba_.size() / 4, bytes_of(bg));
    background_ = bg;
  }
  // Until set_from_spans says otherwise: the fill about to run may stop half-way (bad input).
  spans_only_ = false;
  return canvas_;
}

void TracedImage::set_from_spans(const trace::Trace& t) {
  const std::size_t w = static_cast<std::size_t>(canvas_.width());
  for_each_span(t, [&](i64 y, const trace::Span& span) {
    const Rgb32f* row = canvas_.row(static_cast<int>(y));
    std::uint8_t* out = rgba_.data() + (static_cast<std::size_t>(y) * w + static_cast<std::size_t>(span.x_begin)) * 4;
    for (i64 x = span.x_begin; x < span.x_end; ++x, out += 4) {
      const Rgb32f& p = row[x];
      out[0] = to_byte(p.r);
      out[1] = to_byte(p.g);
      out[2] = to_byte(p.b);
    }
  });
  spans_only_ = true;
}

void TracedImage::set_from_every_pixel() {
  put_rgba(canvas_, rgba_);
  spans_only_ = false;
}

}  // namespace scantrace::web
