#include "grade/diff_picture.hpp"

#include <algorithm>

namespace scantrace::grade {

const std::array<std::array<std::uint8_t, 3>, kCategories.size()> kCategoryColours{{
    {230, 0, 0},      // boundary: red
    {255, 140, 0},    // near_boundary: orange
    {120, 200, 40},   // widened: lime
    {200, 200, 0},    // shifted: olive yellow
    {200, 0, 200},    // order: magenta
    {230, 160, 230},  // order_tie: pale magenta
    {0, 90, 230},     // missing_face: blue
    {40, 40, 40},     // degenerate_drawn: black
    {0, 170, 0},      // colour: green
    {0, 200, 200},    // background: cyan
    {120, 60, 120},   // other: plum
}};

std::vector<std::uint8_t> diff_picture(const DiffReport& r) {
  std::vector<std::uint8_t> out(static_cast<std::size_t>(r.width) * r.height * 3);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * r.width + x;
      std::uint8_t* px = &out[3 * i];
      if (const std::uint8_t cat = r.category_map[i]) {
        std::copy_n(kCategoryColours[cat - 1].begin(), 3, px);
      } else {
        // The reference as light grey: luminance squeezed into [150, 245].
        const Rgb32f c = r.reference(x, y);
        const double l = 0.299 * c.r + 0.587 * c.g + 0.114 * c.b;
        px[0] = px[1] = px[2] = static_cast<std::uint8_t>(150 + 95 * std::clamp(l, 0.0, 1.0));
      }
    }
  return out;
}

}  // namespace scantrace::grade
