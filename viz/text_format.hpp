#pragma once
// Numbers as the frames print them: short, aligned, and never in scientific notation (a student
// compares them with the formula, digit by digit).
#include <cstdint>
#include <string>

#include "src/color.hpp"
#include "src/vec2.hpp"

namespace scantrace::viz {

// At most `decimals` decimals, trailing zeros dropped: 3.8333 -> "3.833", 20.0 -> "20".
std::string display_number(double v, int decimals = 3);
// Exactly `decimals` decimals, for columns that should line up.
std::string fixed(double v, int decimals = 3);
// `v` added or taken away in a formula, its sign as the operator: "+ 0.39", "- 0.39" (never
// "+ -0.39"); minus_term writes "x - v": "- 3.2", or "+ 3.2" for v = -3.2.
std::string plus_term(double v, int decimals = 3);
std::string minus_term(double v, int decimals = 3);
std::string integer(std::int64_t v);                   // 35300 -> "35,300"
std::string point(Vec2 p, int decimals = 2);           // "(20, 80.5)"
std::string colour(const Color& c, int decimals = 3);  // "(0.955, 0.000, 0.045)"

}  // namespace scantrace::viz
