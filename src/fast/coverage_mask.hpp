#pragma once
// Which pixels of an image are already final: one bit per pixel, a row of 64-bit words per image
// row. The near-to-far render (occlusion_canvas.hpp) claims each span against it, so that a pixel
// is written once, by the nearest face, and a face whose box is all covered is not even set up.
//
// Why a bit mask and not a list of covered spans per row: a span of the course scene is ten to
// twenty pixels, one or two words; claiming it is a few ands and a count of trailing zeros,
// whatever the row looks like, where a span list costs a search and an insertion whose length
// grows with the fragmentation of the row.
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace scantrace {

class CoverageMask {
 public:
  // Makes every pixel of a width × height image uncovered, keeping the storage.
  void reset(int width, int height) {
    width_ = width;
    words_ = (width + 63) / 64;
    bits_.assign(static_cast<std::size_t>(words_) * std::max(height, 0), 0);
  }
  int width() const { return width_; }

  // A row's words, for a caller that steps from row to row itself (the sweep keeps the pointer in
  // a register, as it does the image's row: after a store through a byte pointer a member would
  // be reloaded).
  std::uint64_t* row(int y) { return bits_.data() + static_cast<std::size_t>(y) * words_; }
  const std::uint64_t* row(int y) const {
    return bits_.data() + static_cast<std::size_t>(y) * words_;
  }
  std::ptrdiff_t stride() const { return words_; }

  // Visits the runs of pixels [x_begin, x_end) of `row` that are not covered yet, left to right,
  // as visit(a, b) for pixels [a, b), and marks the whole span covered. Returns the pixels
  // visited. The span must be non-empty and lie on the image. Inlined into the sweep: a call per
  // span would save and restore the sweep's registers around every claim.
  template <class Visit>
  [[gnu::always_inline]] static int claim(std::uint64_t* row, int x_begin, int x_end,
                                          Visit&& visit) {
    if (const int w = x_begin >> 6; w == (x_end - 1) >> 6) {
      // Most spans lie in one word, and most of those are either all new or all covered.
      const std::uint64_t in_span = word_bits(x_begin, x_end), free = ~row[w] & in_span;
      if (free == 0) return 0;
      if (free == in_span) {
        row[w] |= in_span;
        visit(x_begin, x_end);
        return x_end - x_begin;
      }
    }
    return claim_runs(row, x_begin, x_end, visit);
  }

  // Marks pixels [x_begin, x_end) of `row` covered, which the caller knows were not.
  [[gnu::always_inline]] static void mark(std::uint64_t* row, int x_begin, int x_end) {
    const int first = x_begin >> 6, last = (x_end - 1) >> 6;
    if (first == last) {
      row[first] |= word_bits(x_begin, x_end);
      return;
    }
    for (int w = first; w <= last; ++w) row[w] |= span_bits(w, x_begin, x_end);
  }

  // Whether every pixel [x_begin, x_end) of `row` is covered (the span non-empty).
  [[gnu::always_inline]] static bool covered(const std::uint64_t* row, int x_begin, int x_end) {
    const int first = x_begin >> 6, last = (x_end - 1) >> 6;
    if (first == last) {
      const std::uint64_t in_span = word_bits(x_begin, x_end);
      return (row[first] & in_span) == in_span;
    }
    for (int w = first; w <= last; ++w) {
      const std::uint64_t in_span = span_bits(w, x_begin, x_end);
      if ((row[w] & in_span) != in_span) return false;
    }
    return true;
  }

  template <class Visit>
  int claim(int y, int x_begin, int x_end, Visit&& visit) {
    return x_begin < x_end ? claim(row(y), x_begin, x_end, visit) : 0;
  }
  void mark(int y, int x_begin, int x_end) {
    if (x_begin < x_end) mark(row(y), x_begin, x_end);
  }

  // How much of pixels [x_begin, x_end) of rows [y_begin, y_end) is covered (none when empty).
  enum class Cover { none, some, all };
  Cover cover(int y_begin, int y_end, int x_begin, int x_end) const {
    if (x_begin >= x_end || y_begin >= y_end) return Cover::none;
    const int first = x_begin >> 6, last = (x_end - 1) >> 6;
    if (first == last) {  // a box within one word, as most faces' are: one and per row
      const std::uint64_t in_box = word_bits(x_begin, x_end);
      const std::uint64_t* r = row(y_begin) + first;
      std::uint64_t any = 0, all = in_box;
      for (int y = y_begin; y < y_end; ++y, r += words_) {
        any |= *r & in_box;
        all &= *r;
        if (any && all != in_box) return Cover::some;
      }
      return all == in_box ? Cover::all : any ? Cover::some : Cover::none;
    }
    bool any = false, all = true;
    for (int y = y_begin; y < y_end; ++y) {
      const std::uint64_t* r = row(y);
      for (int w = first; w <= last; ++w) {
        const std::uint64_t in_span = span_bits(w, x_begin, x_end), on = r[w] & in_span;
        any = any || on != 0;
        all = all && on == in_span;
      }
      if (any && !all) return Cover::some;
    }
    return all ? Cover::all : any ? Cover::some : Cover::none;
  }

  // Whether every pixel [x_begin, x_end) of rows [y_begin, y_end) is covered (true when empty).
  bool covered(int y_begin, int y_end, int x_begin, int x_end) const {
    if (x_begin >= x_end) return true;
    for (int y = y_begin; y < y_end; ++y)
      if (!covered(row(y), x_begin, x_end)) return false;
    return true;
  }
  bool covered(int y, int x_begin, int x_end) const { return covered(y, y + 1, x_begin, x_end); }

 private:
  // claim() of a span over several words, or partly covered: its runs, merged across words.
  template <class Visit>
  static int claim_runs(std::uint64_t* row, int x_begin, int x_end, Visit& visit) {
    int claimed = 0;
    int run_begin = -1, run_end = -1;  // the run not visited yet: it may go on in the next word
    for (int w = x_begin >> 6, last = (x_end - 1) >> 6; w <= last; ++w) {
      const std::uint64_t in_span = span_bits(w, x_begin, x_end);
      std::uint64_t free = ~row[w] & in_span;
      row[w] |= in_span;
      while (free) {
        const int s = std::countr_zero(free);
        const int n = std::countr_one(free >> s);
        const int a = w * 64 + s, b = a + n;
        if (a == run_end) {
          run_end = b;
        } else {
          if (run_begin >= 0) visit(run_begin, run_end);
          run_begin = a, run_end = b;
        }
        claimed += n;
        free = s + n >= 64 ? 0 : free & (~std::uint64_t{0} << (s + n));
      }
    }
    if (run_begin >= 0) visit(run_begin, run_end);
    return claimed;
  }

  // The bits of [x_begin, x_end) in their one word (x_end − 1 in the same word as x_begin).
  static std::uint64_t word_bits(int x_begin, int x_end) {
    return (~std::uint64_t{0} << (x_begin & 63)) & (~std::uint64_t{0} >> (63 - ((x_end - 1) & 63)));
  }
  // The bits of word w that lie in [x_begin, x_end).
  static std::uint64_t span_bits(int w, int x_begin, int x_end) {
    const int lo = std::max(x_begin - w * 64, 0), hi = std::min(x_end - w * 64, 64);
    const std::uint64_t below_hi = hi == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << hi) - 1;
    return below_hi & (~std::uint64_t{0} << lo);
  }

  int width_ = 0, words_ = 0;
  std::vector<std::uint64_t> bits_;
};

}  // namespace scantrace
