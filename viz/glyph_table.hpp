#pragma once
// Each glyph of a frame's text written once (docs/design.md §6, "Text"): the SVG and canvas
// backends draw text as the Hershey strokes, and a frame's labels repeat the same few dozen
// glyphs hundreds of times (the course triangle's step frames: 85 text runs, 27,000 stroke points,
// 90 % of a frame's canvas JSON). A backend asks the table for the id of each glyph it places and
// writes the table once: the glyph's strokes relative to its origin (hershey_glyph_strokes), the
// SVG's <defs> placed by <use>, the canvas JSON's "glyphs" placed by a "G" op.
#include <array>
#include <vector>

#include "viz/hershey.hpp"

namespace scantrace::viz {

class GlyphTable {
 public:
  struct Glyph {
    unsigned char c;
    HersheyFont font;
    double scale;  // quantised (hershey_scale)
  };

  // The id of the glyph (ids count from 0 in the order first asked for). A frame's glyphs come in
  // a few fonts and scales: each pair has the ids of its characters in a table, found by a short
  // scan (a std::map keyed by the triple was a twentieth of composing the explorer's step frame
  // as numbers, in its module on every mouse move of a drag; docs/performance.md, "Ninth round").
  int id(unsigned char c, HersheyFont font, double quantised_scale) {
    Ids* ids = nullptr;
    for (Ids& t : ids_)
      if (t.font == font && t.scale == quantised_scale) {
        ids = &t;
        break;
      }
    if (!ids) {
      ids = &ids_.emplace_back();
      ids->font = font;
      ids->scale = quantised_scale;
      ids->of.fill(-1);
    }
    int& id = ids->of[c];
    if (id < 0) {
      id = static_cast<int>(glyphs_.size());
      glyphs_.push_back({c, font, quantised_scale});
    }
    return id;
  }
  // The glyphs by id.
  const std::vector<Glyph>& glyphs() const { return glyphs_; }
  // Glyph `id`'s polylines relative to its origin.
  std::vector<std::vector<Point2d>> strokes(int id) const {
    const Glyph& g = glyphs_.at(static_cast<std::size_t>(id));
    return hershey_glyph_strokes(g.c, g.font, g.scale);
  }

 private:
  struct Ids {
    HersheyFont font{};
    double scale = 0;
    std::array<int, 256> of{};  // by character; -1: not asked for yet
  };
  std::vector<Ids> ids_;
  std::vector<Glyph> glyphs_;
};

}  // namespace scantrace::viz
