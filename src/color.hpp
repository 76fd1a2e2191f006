#pragma once
// RGB colour with components in [0, 1] (docs/design.md §2). Arithmetic is in double so that
// interpolation over long spans keeps well inside the 1e-4 accuracy budget; conversion to 8 bits
// and to OpenCV's BGR order happens only at the file boundary.

namespace scantrace {

struct Color {
  double r = 0, g = 0, b = 0;

  friend constexpr Color operator+(Color a, Color b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }
  friend constexpr Color operator-(Color a, Color b) { return {a.r - b.r, a.g - b.g, a.b - b.b}; }
  friend constexpr Color operator*(Color a, double s) { return {a.r * s, a.g * s, a.b * s}; }
  friend constexpr Color operator*(double s, Color a) { return a * s; }
  constexpr Color& operator+=(Color o) { return *this = *this + o; }
  friend constexpr bool operator==(Color, Color) = default;
};

}  // namespace scantrace
