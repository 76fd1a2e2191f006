#pragma once
// Comparing a filled image with the reference, pixel by pixel, with a readable account of the
// first difference (the whole image would drown the report).
#include <cmath>
#include <cstdio>
#include <functional>
#include <span>
#include <string>

#include "reference_raster.hpp"
#include "src/image.hpp"

namespace sttest {

// A background no fill can produce (colours are convex combinations of colours in [0, 1]), so a
// pixel differing from it was written.
inline constexpr scantrace::Rgb32f kSentinel{-1.0f, -1.0f, -1.0f};

inline std::string format_points(std::span<const scantrace::Vec2> pts) {
  std::string s;
  char buf[96];
  for (const scantrace::Vec2& p : pts) {
    std::snprintf(buf, sizeof buf, "(%.17g, %.17g) ", p.x, p.y);
    s += buf;
  }
  return s;
}

inline std::string format_color(scantrace::Color c) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g)", c.r, c.g, c.b);
  return buf;
}

// The canvas stores float32: a colour in [0, 1] is rounded by at most 2^-24 when stored, on top of
// whatever error the fill made. `tol` is the fill's error allowed beyond that rounding.
inline constexpr double kFloatStorage = 0x1p-24;

inline bool near(scantrace::Rgb32f p, scantrace::Color c, double tol) {
  const double t = tol + kFloatStorage;
  return std::fabs(p.r - c.r) <= t && std::fabs(p.g - c.g) <= t && std::fabs(p.b - c.b) <= t;
}

// "" when `img` is written exactly where `ref` covers and every written pixel is within `tol` of
// `expected(x, y)`; otherwise a description of the first differing pixel in row-major order.
inline std::string first_difference(const scantrace::RgbImage& img, const RefRaster& ref,
                                    const std::function<scantrace::Color(int, int)>& expected,
                                    double tol) {
  char buf[256];
  for (int y = 0; y < img.height(); ++y) {
    for (int x = 0; x < img.width(); ++x) {
      const scantrace::Rgb32f p = img(x, y);
      const bool written = !(p == kSentinel);
      if (written != ref.at(x, y)) {
        std::snprintf(buf, sizeof buf, "pixel (%d, %d): reference %s, fill %s", x, y,
                      ref.at(x, y) ? "covers it" : "does not cover it",
                      written ? "wrote it" : "did not write it");
        return buf;
      }
      if (written && !near(p, expected(x, y), tol)) {
        std::snprintf(buf, sizeof buf, "pixel (%d, %d): colour %s, expected %s", x, y,
                      format_color(p.color()).c_str(), format_color(expected(x, y)).c_str());
        return buf;
      }
    }
  }
  return "";
}

}  // namespace sttest
