#include "viz/hershey.hpp"

#include <cmath>
#include <string>
#include <string_view>

namespace scantrace::viz {
namespace {

#include "viz/hershey/glyphs.inc"

// The font's lines, as OpenCV's font tables give them (cap line 12, base line 9 for both).
constexpr int kCapLine = 12, kBaseLine = 9;

int cv_round_int(double v) {
  return static_cast<int>(std::lrint(v));
}

const char* glyph(HersheyFont font, unsigned char c) {
  const char* const* table = font == HersheyFont::simplex ? kSimplex : kDuplex;
  return table[c - ' '];
}

// The Hershey fonts are ASCII. Typographic characters a caption or a file name may hold are
// drawn as their ASCII look-alikes (a scene named "Maria’s scene" must not read "Maria?s"): the
// UTF-8 code point -> the ASCII text drawn for it.
struct AsciiFold {
  char32_t code;
  std::string_view ascii;
};
constexpr AsciiFold kAsciiFolds[] = {
    {U'\u00A0', " "},   {U'\u00B7', "."},   {U'\u00D7', "x"},   {U'\u2010', "-"},
    {U'\u2011', "-"},   {U'\u2012', "-"},   {U'\u2013', "-"},   {U'\u2014', "-"},
    {U'\u2018', "'"},   {U'\u2019', "'"},   {U'\u201A', "'"},   {U'\u201C', "\""},
    {U'\u201D', "\""}, {U'\u201E', "\""}, {U'\u2022', "*"},   {U'\u2026', "..."},
    {U'\u2032', "'"},   {U'\u2033', "\""}, {U'\u2192', "->"},  {U'\u2190', "<-"},
    {U'\u2212', "-"},   {U'\u2248', "~"},   {U'\u2264', "<="},  {U'\u2265', ">="},
    {U'\u2260', "!="},
};

// The code point of the UTF-8 sequence starting at text[i] (0 when malformed); `i` is left on
// its last byte.
char32_t next_code_point(std::string_view text, std::size_t& i) {
  const auto lead = static_cast<unsigned char>(text[i]);
  const int extra = lead >= 0xF0 ? 3 : lead >= 0xE0 ? 2 : lead >= 0xC0 ? 1 : 0;
  char32_t code = extra == 3 ? lead & 0x07 : extra == 2 ? lead & 0x0F : lead & 0x1F;
  int seen = 0;
  while (i + 1 < text.size() && (static_cast<unsigned char>(text[i + 1]) & 0xC0) == 0x80) {
    code = (code << 6) | (static_cast<unsigned char>(text[++i]) & 0x3F);
    ++seen;
  }
  return seen == extra && extra > 0 ? code : 0;
}

// The characters drawn for `text`: printable ASCII as it is, the typographic characters above as
// their look-alikes, and '?' for anything else (a UTF-8 sequence is one '?'), as OpenCV's putText
// draws what it cannot.
template <class F>
void for_each_char(std::string_view text, F&& f) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      const char32_t code = next_code_point(text, i);
      std::string_view ascii = "?";
      for (const AsciiFold& fold : kAsciiFolds)
        if (fold.code == code) ascii = fold.ascii;
      for (const char a : ascii) f(static_cast<unsigned char>(a));
      continue;
    }
    if (c < ' ' || c > '~') c = '?';
    f(c);
  }
}

}  // namespace

std::string hershey_ascii(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for_each_char(text, [&](unsigned char c) { out += static_cast<char>(c); });
  return out;
}

Size hershey_text_size(std::string_view text, HersheyFont font, double scale, int thickness,
                       int* baseline) {
  double view_x = 0;
  for_each_char(text, [&](unsigned char c) {
    const char* g = glyph(font, c);
    view_x += ((g[1] - 'R') - (g[0] - 'R')) * scale;
  });
  if (baseline) *baseline = cv_round_int(kBaseLine * scale + thickness * 0.5);
  return {cv_round_int(view_x + thickness),
          cv_round_int((kCapLine + kBaseLine) * scale + (thickness + 1) / 2)};
}

double hershey_scale(double scale) {
  return std::lrint(scale * 65536) / 65536.0;
}

std::vector<PlacedGlyph> hershey_layout(std::string_view text, HersheyFont font, double scale,
                                        Point origin) {
  // putText puts the glyphs' y = 9 on the baseline and moves each glyph by its left bearing.
  const double s = hershey_scale(scale);
  double x = origin.x;
  const double y = origin.y - kBaseLine * s;
  std::vector<PlacedGlyph> out;
  for_each_char(text, [&](unsigned char c) {
    const char* g = glyph(font, c);
    x -= (g[0] - 'R') * s;
    out.push_back({c, {x, y}});
    x += (g[1] - 'R') * s;
  });
  return out;
}

std::vector<std::vector<Point2d>> hershey_glyph_strokes(unsigned char c, HersheyFont font,
                                                        double s) {
  std::vector<std::vector<Point2d>> strokes;
  std::vector<Point2d> stroke;
  for (const char* p = glyph(font, c) + 2; *p && p[1]; p += 2) {
    if (p[0] == ' ' && p[1] == 'R') {  // pen up
      if (stroke.size() > 1) strokes.push_back(std::move(stroke));
      stroke.clear();
      continue;
    }
    stroke.push_back({(p[0] - 'R') * s, (p[1] - 'R') * s});
  }
  if (stroke.size() > 1) strokes.push_back(std::move(stroke));
  return strokes;
}

std::vector<std::vector<Point2d>> hershey_strokes(std::string_view text, HersheyFont font,
                                                  double scale, Point origin) {
  const double s = hershey_scale(scale);
  std::vector<std::vector<Point2d>> strokes;
  for (const PlacedGlyph& g : hershey_layout(text, font, scale, origin))
    for (std::vector<Point2d> stroke : hershey_glyph_strokes(g.c, font, s)) {
      for (Point2d& p : stroke) p = {g.origin.x + p.x, g.origin.y + p.y};
      strokes.push_back(std::move(stroke));
    }
  return strokes;
}

}  // namespace scantrace::viz
