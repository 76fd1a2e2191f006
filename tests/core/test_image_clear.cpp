// Image's clear (reset, fill_all): every pixel becomes the value, whichever way it is written (a
// memset for a pixel of one repeated byte, block copies otherwise), at sizes around the copy
// block and after the image held other pixels. Checked pixel by pixel against the value.
#include <catch2/catch.hpp>

#include <cstdint>
#include <utility>

#include "src/image.hpp"

using namespace scantrace;

namespace {

struct Gray16 {  // two bytes, equal or not
  std::uint16_t v;
  bool operator==(const Gray16&) const = default;
};

template <class P>
void check_all(const Image<P>& img, P value) {
  long long wrong = 0;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) wrong += !(img(x, y) == value);
  INFO(img.width() << " x " << img.height());
  CHECK(wrong == 0);
}

template <class P>
void clear_each_way(P a, P b) {
  // Sizes: one pixel, less than a block, the block's edges, several blocks and a tail, and a
  // large image (each row 3,000 pixels).
  for (const auto& [w, h] :
       {std::pair{1, 1}, {7, 3}, {2730, 1}, {2731, 1}, {2732, 2}, {3000, 700}}) {
    Image<P> img(w, h, a);
    check_all(img, a);
    img.fill_all(b);
    check_all(img, b);
    img.reset(h, w, a);  // the same pixel count, other shape: storage kept, every pixel written
    check_all(img, a);
  }
}

}  // namespace

TEST_CASE("an image clears to its value, memset or not", "[image]") {
  // Bytes all equal (memset) against bytes that differ in one place only: a check that compared
  // fewer bytes than the pixel has would memset the second with 255 and fail here.
  clear_each_way(Bgr8{255, 255, 255}, Bgr8{255, 255, 254});
  clear_each_way(Bgr8{0, 0, 0}, Bgr8{0, 7, 0});
  clear_each_way(Bgr8{9, 8, 7}, Bgr8{0x80, 0x80, 0x80});
  clear_each_way(Gray16{0x0101}, Gray16{0x0102});
  clear_each_way(Rgb32f{1, 1, 1}, Rgb32f{0, 0, 0});
  clear_each_way(Rgb32f{-0.0f, 0, 0}, Rgb32f{0.25f, 0.5f, 0.75f});
}
