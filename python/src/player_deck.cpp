#include "player_deck.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <variant>
#include <vector>

#include "viz/frame_json.hpp"
#include "viz/frame_text.hpp"
#include "viz/step_label.hpp"

namespace scantrace::python {
namespace {

// The glyph data viz/hershey.cpp draws from (generated once, included here as data).
#include "viz/hershey/glyphs.inc"

using viz::frame_text::hex_colour;
using viz::frame_text::json_string;

// The characters viz::hershey_strokes draws for `text` (printable ASCII; anything else one '?'
// per UTF-8 sequence), so that the deck carries the glyphs player.js needs.
void note_glyphs(std::string_view text, std::set<unsigned char>& used) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80)
      while (i + 1 < text.size() && (static_cast<unsigned char>(text[i + 1]) & 0xC0) == 0x80) ++i;
    used.insert(c < ' ' || c > '~' ? '?' : c);
  }
}

void write_glyphs(std::ostringstream& out,
                  const std::map<viz::HersheyFont, std::set<unsigned char>>& glyphs) {
  out << "\"glyphs\":{";
  bool first_font = true;
  for (const auto& [font, chars] : glyphs) {
    const char* const* table = font == viz::HersheyFont::simplex ? kSimplex : kDuplex;
    out << (first_font ? "" : ",") << "\"" << static_cast<int>(font) << "\":{";
    first_font = false;
    bool first = true;
    for (unsigned char c : chars) {
      out << (first ? "" : ",") << json_string(std::string(1, static_cast<char>(c))) << ":"
          << json_string(table[c - ' ']);
      first = false;
    }
    out << "}";
  }
  out << "}";
}

// Lines drawn one after another in the same style, unmarked: a scene's batch outlines thousands of
// triangles (3 ops each), a grid its cell borders. Written as one op of connected chains,
//   ["l", clip, null, colour, thickness, shift, [[x0, y0, x1, y1, ...], ...]]
// in the ops' own 1/2^shift units (a chain joins segments that continue one another).
bool groupable(const viz::DrawOp& a, const viz::DrawOp& b) {
  const auto* l = std::get_if<viz::LineOp>(&a.body);
  const auto* m = std::get_if<viz::LineOp>(&b.body);
  return l && m && !a.mark && !b.mark && a.clip == b.clip && l->colour == m->colour &&
         l->thickness == m->thickness && l->shift == m->shift;
}

std::string line_group_json(const std::vector<viz::DrawOp>& ops, std::size_t first,
                            std::size_t last) {
  const auto& l0 = std::get<viz::LineOp>(ops[first].body);
  std::ostringstream out;
  out << "[\"l\",";
  if (const auto& c = ops[first].clip)
    out << "[" << c->x << "," << c->y << "," << c->width << "," << c->height << "]";
  else
    out << "null";
  out << ",null,\"" << hex_colour(l0.colour) << "\"," << l0.thickness << "," << l0.shift << ",[";
  std::optional<viz::Point> end;
  for (std::size_t i = first; i <= last; ++i) {
    const auto& l = std::get<viz::LineOp>(ops[i].body);
    if (end && *end == l.a) {
      out << "," << l.b.x << "," << l.b.y;
    } else {
      out << (end ? "]," : "") << "[" << l.a.x << "," << l.a.y << "," << l.b.x << "," << l.b.y;
    }
    end = l.b;
  }
  out << "]]]";
  return out.str();
}

// The distinct ops of a deck, numbered in order of first use.
class OpTable {
 public:
  // Lines first..last of `ops` (groupable() one after another) as one op.
  std::size_t add_lines(const std::vector<viz::DrawOp>& ops, std::size_t first, std::size_t last) {
    return first == last ? add(ops[first]) : intern(line_group_json(ops, first, last));
  }

  std::size_t add(const viz::DrawOp& op) {
    if (const auto* t = std::get_if<viz::TextOp>(&op.body)) note_glyphs(t->text, glyphs_[t->font]);
    const auto* p = std::get_if<viz::PixelsOp>(&op.body);
    if (!p || p->area.area() < 2) return intern(viz::to_json(op, viz::TextForm::text_with_font));
    // A block of pixels at the place of an earlier one (the same view, one step later) mostly
    // holds the same pixels: only the rectangle that changed is stored, over the earlier op.
    const auto key =
        std::make_pair(op.clip ? std::array{op.clip->x, op.clip->y, op.clip->width, op.clip->height}
                               : std::array{0, 0, -1, -1},
                       std::array{p->area.x, p->area.y, p->area.width, p->area.height});
    const auto earlier = blocks_.find(key);
    std::size_t id;
    if (earlier == blocks_.end()) {
      id = intern(viz::to_json(op, viz::TextForm::text_with_font));
    } else {
      const viz::Rect changed = changed_rect(*earlier->second.second, *p);
      if (changed.area() * 2 > p->area.area()) {
        id = intern(viz::to_json(op, viz::TextForm::text_with_font));
      } else {
        viz::DrawOp patch = op;
        patch.body = crop(*p, changed);
        std::string json = viz::to_json(patch, viz::TextForm::text_with_font);
        json.replace(0, 4, "[\"p\"");
        json.back() = ',';
        id = intern(json + std::to_string(earlier->second.first) + "]");
      }
    }
    blocks_[key] = {id, p->bgr};
    return id;
  }

  const std::vector<const std::string*>& ops() const { return ops_; }
  const std::map<viz::HersheyFont, std::set<unsigned char>>& glyphs() const { return glyphs_; }

 private:
  std::size_t intern(std::string json) {
    auto [it, added] = index_.try_emplace(std::move(json), index_.size());
    if (added) ops_.push_back(&it->first);
    return it->second;
  }

  // The smallest rectangle (in the block's coordinates, at least 2 pixels: a 1-pixel block is
  // written as a rectangle) outside which `now` equals `before`, pixel for pixel.
  static viz::Rect changed_rect(const std::vector<viz::Vec3b>& before, const viz::PixelsOp& now) {
    const int w = now.area.width, h = now.area.height;
    int x0 = w, y0 = h, x1 = -1, y1 = -1;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + x;
        if (before[i] == (*now.bgr)[i]) continue;
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
    if (x1 < 0) x0 = y0 = x1 = y1 = 0;
    if (x1 == x0 && y1 == y0) (x1 + 1 < w ? x1 : y1) += 1;
    return {now.area.x + x0, now.area.y + y0, x1 - x0 + 1, y1 - y0 + 1};
  }

  static viz::PixelsOp crop(const viz::PixelsOp& p, const viz::Rect& r) {
    auto out = std::make_shared<std::vector<viz::Vec3b>>();
    out->reserve(static_cast<std::size_t>(r.area()));
    for (int y = r.y; y < r.y + r.height; ++y)
      for (int x = r.x; x < r.x + r.width; ++x)
        out->push_back((*p.bgr)[static_cast<std::size_t>(y - p.area.y) * p.area.width +
                                static_cast<std::size_t>(x - p.area.x)]);
    return {r, std::move(out)};
  }

  std::unordered_map<std::string, std::size_t> index_;
  std::vector<const std::string*> ops_;  // keys of index_, by number
  std::map<viz::HersheyFont, std::set<unsigned char>> glyphs_;
  // The last block drawn at each place (clip, area): its op and its pixels.
  std::map<std::pair<std::array<int, 4>, std::array<int, 4>>,
           std::pair<std::size_t, std::shared_ptr<const std::vector<viz::Vec3b>>>>
      blocks_;
};

}  // namespace

Deck write_deck(viz::FrameSequence& frames, std::size_t first, std::size_t last) {
  OpTable table;
  std::ostringstream runs, labels, rows;
  viz::Size size;
  viz::Scalar background;
  for (std::size_t i = first; i <= last; ++i) {
    const viz::Frame f = frames.frame(i);
    size = f.size(), background = f.background();
    // Runs of consecutive op indices: a frame's new ops are numbered consecutively as they come.
    std::vector<std::size_t> ids;
    const std::vector<viz::DrawOp>& ops = f.ops();
    for (std::size_t k = 0; k < ops.size(); ++k) {
      std::size_t end = k;
      while (end + 1 < ops.size() && groupable(ops[k], ops[end + 1])) ++end;
      ids.push_back(end > k ? table.add_lines(ops, k, end) : table.add(ops[k]));
      k = end;
    }
    runs << (i == first ? "[" : ",\n[");
    for (std::size_t k = 0; k < ids.size();) {
      std::size_t n = 1;
      while (k + n < ids.size() && ids[k + n] == ids[k] + n) ++n;
      runs << (k ? "," : "") << ids[k] << "," << n;
      k += n;
    }
    runs << "]";
    labels << (i == first ? "" : ",")
           << json_string(viz::step_label(frames.plan(), frames.steps()[i]));
    // The scanlines a step shows, for the player's g (go to a row's step).
    const viz::Step& s = frames.steps()[i];
    rows << (i == first ? "" : ",");
    if (s.kind == viz::StepKind::scanlines)
      rows << "[" << s.first_row << "," << s.last_row << "]";
    else
      rows << "null";
  }
  std::ostringstream out;
  out << "{\"w\":" << size.width << ",\"h\":" << size.height << ",\"bg\":\""
      << hex_colour(background) << "\",";
  write_glyphs(out, table.glyphs());
  out << ",\n\"ops\":[";
  const auto& ops = table.ops();
  for (std::size_t k = 0; k < ops.size(); ++k) out << (k ? ",\n" : "") << *ops[k];
  out << "],\n\"frames\":[" << runs.str() << "],\n\"labels\":[" << labels.str() << "],\n\"rows\":["
      << rows.str() << "]}";
  return {out.str(), last - first + 1, ops.size()};
}

}  // namespace scantrace::python
