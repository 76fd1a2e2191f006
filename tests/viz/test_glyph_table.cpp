// viz::GlyphTable: each glyph of a frame (a character in a font at a scale) gets one id, counted
// from 0 in the order first asked for; the same glyph asked again gets the same id, and a
// character in another font or at another scale is another glyph. Checked against a table kept
// here by linear search over the glyphs asked for, on a long random sequence.
#include <catch2/catch.hpp>

#include <random>

#include "viz/glyph_table.hpp"

using namespace scantrace::viz;

TEST_CASE("glyph ids count from 0 in the order first asked for, one per character, font and scale") {
  GlyphTable table;
  struct Asked {
    unsigned char c;
    HersheyFont font;
    double scale;
  };
  std::vector<Asked> firsts;  // the reference: the glyphs in the order first asked for
  std::mt19937 rng(7);
  const double scales[] = {0.5, 0.625, 1.0, -0.0, 0.0};
  for (int i = 0; i < 20000; ++i) {
    const Asked a{static_cast<unsigned char>(rng() % 256), rng() % 2 ? HersheyFont::duplex : HersheyFont::simplex,
                  scales[rng() % 5]};
    std::size_t want = 0;
    // -0.0 and 0.0 are one scale (they compare equal), as they were as the key of a std::map.
    while (want < firsts.size() && !(firsts[want].c == a.c && firsts[want].font == a.font &&
                                     firsts[want].scale == a.scale))
      ++want;
    if (want == firsts.size()) firsts.push_back(a);
    REQUIRE(table.id(a.c, a.font, a.scale) == static_cast<int>(want));
  }
  REQUIRE(table.glyphs().size() == firsts.size());
  CHECK(firsts.size() > 1000);  // 256 characters x 2 fonts x 4 scales, most of them asked for
  for (std::size_t i = 0; i < firsts.size(); ++i) {
    CHECK(table.glyphs()[i].c == firsts[i].c);
    CHECK(table.glyphs()[i].font == firsts[i].font);
    CHECK(table.glyphs()[i].scale == firsts[i].scale);
  }
}
