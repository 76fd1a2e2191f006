#include "viz/text_format.hpp"

#include <cmath>
#include <cstdio>

#include <spdlog/fmt/fmt.h>

namespace scantrace::viz {

std::string fixed(double v, int decimals) {
  if (!std::isfinite(v)) return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  // Huge coordinates (a vertex at 1e9) still print as plain digits.
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);  // "-0.000"
  return s;
}

std::string plus_term(double v, int decimals) {
  const std::string magnitude = display_number(std::abs(v), decimals);
  return (v < 0 && magnitude != "0" ? "- " : "+ ") + magnitude;
}

std::string minus_term(double v, int decimals) {
  const std::string magnitude = display_number(std::abs(v), decimals);
  return (v < 0 && magnitude != "0" ? "+ " : "- ") + magnitude;
}

std::string display_number(double v, int decimals) {
  std::string s = fixed(v, decimals);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

std::string integer(std::int64_t v) {
  const std::uint64_t magnitude =
      v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
  const std::string digits = std::to_string(magnitude);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return v < 0 ? fmt::format("-{}", out) : out;
}

std::string point(Vec2 p, int decimals) {
  return fmt::format("({}, {})", display_number(p.x, decimals), display_number(p.y, decimals));
}

std::string colour(const Color& c, int decimals) {
  return fmt::format("({}, {}, {})", fixed(c.r, decimals), fixed(c.g, decimals),
                     fixed(c.b, decimals));
}

}  // namespace scantrace::viz
