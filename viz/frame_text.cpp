#include "viz/frame_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "io/png_writer.hpp"

namespace scantrace::viz::frame_text {

namespace {

// The cents %.2f prints of v at a tie's neighbourhood: v·100 rounded (r) is within 1e-6 of the
// tie t = floor(r) + 0.5, where rounding r says nothing, and %.2f rounds v's exact binary value,
// half to even on the tie itself. Decided exactly, in integers: with |v| = m / 2^s (m below 2^53),
// 200·|v| = 200·m / 2^s (200·m below 2^61) against the odd integer |2t|. (Not snprintf and
// strtod: emscripten emulates their long double, too slow for a frame per drag move;
// docs/performance.md.)
long long cents_at_tie(double v, double r) {
  const auto k = static_cast<std::uint64_t>(std::llabs(2 * static_cast<long long>(std::floor(r)) + 1));
  const std::uint64_t below = (k - 1) / 2, above = below + 1;  // |cents| on either side
  int e = 0;
  const double f = std::frexp(std::abs(v), &e);  // |v| = f·2^e, f in [0.5, 1)
  const auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));
  const int shift = 53 - e;  // |v| = m / 2^shift; shift > 0 since |v| < 1e7
  std::uint64_t magnitude = below;
  if (shift < 64) {
    const std::uint64_t scaled = 200 * m, whole = scaled >> shift;
    const std::uint64_t rest = scaled & ((std::uint64_t{1} << shift) - 1);
    if (whole > k || (whole == k && rest != 0))
      magnitude = above;
    else if (whole == k)  // exactly the tie: to the even one
      magnitude = below % 2 == 0 ? below : above;
  }
  const auto n = static_cast<long long>(magnitude);
  return v < 0 ? -n : n;
}

// Two decimals by v·100 rounded to the nearest integer, which is what %.2f prints, decided
// exactly within 1e-6 of a tie (cents_at_tie); false when v·100 is too large for its rounding
// error to stay below that (|v·100| < 1e9: below 1.2e-7), or not finite.
bool cents(double v, long long& n) {
  const double r = v * 100;
  if (!(std::abs(r) < 1e9)) return false;
  n = std::abs(r - std::floor(r) - 0.5) > 1e-6 ? std::llround(r) : cents_at_tie(v, r);
  return true;
}

}  // namespace

std::string markup_number(double v) {
  // Two decimals are finer than any backend draws; trailing zeros dropped. A frame's canvas JSON
  // prints thousands of these (the text's strokes), and snprintf of a double is slow where long
  // double is emulated (emscripten's musl: 43 ms of a frame's 137 in the explorer's module):
  // snprintf only where cents() cannot say (|v| of 10^7 or more, or not finite).
  if (long long n = 0; cents(v, n)) {
    if (n == 0) return "0";
    const long long m = n < 0 ? -n : n;
    std::string s;  // not "-" + to_string(...): GCC 12's -Wrestrict false positive (frame_json.cpp)
    if (n < 0) s += '-';
    s += std::to_string(m / 100);
    if (const int c = static_cast<int>(m % 100); c != 0) {
      s += '.';
      s += static_cast<char>('0' + c / 10);
      if (c % 10) s += static_cast<char>('0' + c % 10);
    }
    return s;
  }
  return number_by_printf(v);
}

double number_value(double v) {
  // n / 100.0 is the double nearest n/100 (IEEE division rounds correctly), as is what a JSON
  // reader makes of markup_number()'s digits; "0" for -0.004 too.
  if (long long n = 0; cents(v, n)) return n == 0 ? 0.0 : static_cast<double>(n) / 100.0;
  return std::strtod(number_by_printf(v).c_str(), nullptr);
}

std::string number_by_printf(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s(buf);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

std::string hex_colour(const Scalar& c) {
  // Without snprintf, slow in emscripten (docs/performance.md): every op writes a colour.
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out = "#000000";
  for (int i = 0; i < 3; ++i) {
    const auto v = static_cast<unsigned>(std::clamp(std::lround(c[2 - i]), 0L, 255L));
    out[static_cast<std::size_t>(1 + 2 * i)] = kHex[v >> 4];
    out[static_cast<std::size_t>(2 + 2 * i)] = kHex[v & 15];
  }
  return out;
}

namespace {

// The code point of the well-formed UTF-8 sequence at s[i] (RFC 3629: no overlong form, no
// surrogate, nothing above U+10FFFF) and its length; 0 when none starts there.
std::size_t utf8_at(const std::string& s, std::size_t i, char32_t& cp) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = byte(i);
  std::size_t n = 1;
  char32_t least = 0;
  if (c < 0x80) {
    cp = c;
    return 1;
  }
  if (c >= 0xC2 && c <= 0xDF) n = 2, cp = c & 0x1Fu, least = 0x80;
  else if (c >= 0xE0 && c <= 0xEF) n = 3, cp = c & 0x0Fu, least = 0x800;
  else if (c >= 0xF0 && c <= 0xF4) n = 4, cp = c & 0x07u, least = 0x10000;
  else return 0;
  if (s.size() - i < n) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    cp = cp << 6 | (byte(i + k) & 0x3Fu);
  }
  if (cp < least || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return n;
}

// XML 1.0's Char production (§2.2): what a document may hold at all, escaped or not.
bool xml_char(char32_t c) {
  return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) ||
         (c >= 0xE000 && c <= 0xFFFD) || (c >= 0x10000 && c <= 0x10FFFF);
}

}  // namespace

std::string xml_escape(const std::string& s) {
  // A trace's strings (its generator, its file's name) are anyone's bytes: a character XML 1.0
  // forbids (ESC, U+FFFF) or a byte that is not UTF-8 made the SVG frame a document no parser
  // reads ("PCDATA invalid Char value 27"). XML has no escape for them (&#27; is not
  // well-formed either): each becomes U+FFFD, as a UTF-8 decoder shows a byte it cannot read.
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    char32_t cp = 0;
    const std::size_t n = utf8_at(s, i, cp);
    if (n == 0 || !xml_char(cp)) {
      out += "\xEF\xBF\xBD";  // U+FFFD
      i += n == 0 ? 1 : n;
      continue;
    }
    switch (cp) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out.append(s, i, n);
    }
    i += n;
  }
  return out;
}

std::string png_data_uri(const PixelsOp& p) {
  RgbImage image(p.area.width, p.area.height);
  for (int y = 0; y < p.area.height; ++y)
    for (int x = 0; x < p.area.width; ++x) {
      const Vec3b& c = (*p.bgr)[static_cast<std::size_t>(y) * p.area.width + x];
      image(x, y) = {c[2] / 255.0f, c[1] / 255.0f, c[0] / 255.0f};
    }
  return "data:image/png;base64," + base64(png::encode(image));
}

std::string base64(std::string_view bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
    out += kDigits[v >> 18 & 63];
    out += kDigits[v >> 12 & 63];
    out += kDigits[v >> 6 & 63];
    out += kDigits[v & 63];
  }
  if (const std::size_t rest = bytes.size() - i; rest > 0) {
    const unsigned v = byte(i) << 16 | (rest == 2 ? byte(i + 1) << 8 : 0);
    out += kDigits[v >> 18 & 63];
    out += kDigits[v >> 12 & 63];
    out += rest == 2 ? kDigits[v >> 6 & 63] : '=';
    out += '=';
  }
  return out;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned char>(c));
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace scantrace::viz::frame_text
