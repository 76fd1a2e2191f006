#include "viz/hershey.hpp"

#include <cmath>

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

// The characters OpenCV draws for `text`: printable ASCII as it is, and '?' for anything else (a
// UTF-8 sequence is one '?').
template <class F>
void for_each_char(std::string_view text, F&& f) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      while (i + 1 < text.size() && (static_cast<unsigned char>(text[i + 1]) & 0xC0) == 0x80) ++i;
      c = '?';
    } else if (c < ' ' || c > '~') {
      c = '?';
    }
    f(c);
  }
}

}  // namespace

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
