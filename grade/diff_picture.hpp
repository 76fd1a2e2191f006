#pragma once
// The picture part of diff.png, without OpenCV: the reference in light grey and every differing
// pixel in the colour of its category, at the scene's canvas size. diff_image.hpp adds the legend
// and the magnified inset (OpenCV's text and resize); the Python module shows this picture as is.
#include <array>
#include <cstdint>
#include <vector>

#include "grade/diff_report.hpp"

namespace scantrace::grade {

// One distinct colour per category (RGB), in kCategories' order.
extern const std::array<std::array<std::uint8_t, 3>, kCategories.size()> kCategoryColours;

// width × height × 3 bytes, RGB, row-major.
std::vector<std::uint8_t> diff_picture(const DiffReport& report);

}  // namespace scantrace::grade
