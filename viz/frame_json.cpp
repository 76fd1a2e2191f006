#include "viz/frame_json.hpp"

#include <cstdio>
#include <initializer_list>
#include <map>
#include <optional>
#include <tuple>

#include <spdlog/fmt/fmt.h>

#include "viz/frame_text.hpp"
#include "viz/glyph_table.hpp"
#include "viz/web_player_files.hpp"

namespace scantrace::viz {
namespace {

using frame_text::hex_colour;
using frame_text::json_string;
using frame_text::markup_number;

std::string box(const Rect& r) {
  // fmt, not "[" + std::to_string(...): GCC 12 warns (-Wrestrict, a false positive) on a literal
  // plus a temporary string, the one warning a newcomer's first build printed.
  return fmt::format("[{},{},{},{}]", r.x, r.y, r.width, r.height);
}

// Appends to a string: the ostream this wrote to cost a third of a frame's JSON in the
// WebAssembly build (libc++'s stream sentries and locale lookups per `<<`), and the explorer
// writes a frame on every mouse move of a drag.
void put(std::string& out, const std::string& s) { out += s; }
void put(std::string& out, const char* s) { out += s; }
void put(std::string& out, char c) { out += c; }
void put(std::string& out, int v) { out += std::to_string(v); }
template <class... Parts>
void put_all(std::string& out, const Parts&... parts) {
  (put(out, parts), ...);
}

// A polyline's points as JSON numbers, "x,y,x,y,...".
void put_points(std::string& out, const std::vector<Point2d>& stroke) {
  for (std::size_t i = 0; i < stroke.size(); ++i)
    put_all(out, i ? "," : "", markup_number(stroke[i].x), ',', markup_number(stroke[i].y));
}

// A block of one pixel (a grid's centre dot) is written as a filled rectangle, not an image.
std::optional<RectOp> as_rect(const PixelsOp& p) {
  if (p.area.area() != 1) return std::nullopt;
  const Vec3b& c = p.bgr->front();
  return RectOp{p.area, Scalar(c[0], c[1], c[2]), FILLED};
}

struct Writer {
  std::string& out;
  TextForm text_form = TextForm::strokes;
  GlyphTable* glyphs = nullptr;        // TextForm::glyph_table: the frame's table
  const BlockWriter* block = nullptr;  // a pixel block's data (empty: the PNG data URI)
  void operator()(const RectOp& r) const {
    put_all(out, "\"R\",", r.rect.x, ',', r.rect.y, ',', r.rect.width, ',', r.rect.height, ",\"",
            hex_colour(r.colour), "\",", r.thickness);
  }
  void operator()(const LineOp& l) const {
    const double s = 1.0 / (1 << l.shift);
    put_all(out, "\"L\",", markup_number(l.a.x * s), ',', markup_number(l.a.y * s), ',',
            markup_number(l.b.x * s), ',', markup_number(l.b.y * s), ",\"", hex_colour(l.colour),
            "\",", l.thickness);
  }
  void operator()(const CircleOp& c) const {
    put_all(out, "\"C\",", c.centre.x, ',', c.centre.y, ',', c.radius, ",\"", hex_colour(c.colour),
            "\",", c.thickness);
  }
  void operator()(const TextOp& t) const {
    if (text_form == TextForm::text_with_font) {
      char scale[32];
      std::snprintf(scale, sizeof scale, "%.17g", t.scale);
      put_all(out, "\"t\",", json_string(t.text), ",\"", hex_colour(t.colour), "\",", t.thickness,
              ',', static_cast<int>(t.font), ',', scale, ',', t.origin.x, ',', t.origin.y);
      return;
    }
    const bool table = text_form == TextForm::glyph_table && glyphs;
    put_all(out, table ? "\"G\"," : "\"T\",", json_string(t.text), ",\"", hex_colour(t.colour),
            "\",", t.thickness, ",[");
    if (table) {  // each glyph by its id in the table, at its origin
      const double s = hershey_scale(t.scale);
      bool first = true;
      for (const PlacedGlyph& g : hershey_layout(t.text, t.font, t.scale, t.origin)) {
        put_all(out, first ? "" : ",", glyphs->id(g.c, t.font, s), ',', markup_number(g.origin.x),
                ',', markup_number(g.origin.y));
        first = false;
      }
      out += ']';
      return;
    }
    bool first_stroke = true;
    for (const auto& stroke : hershey_strokes(t.text, t.font, t.scale, t.origin)) {
      out += first_stroke ? "[" : ",[";
      first_stroke = false;
      put_points(out, stroke);
      out += ']';
    }
    out += ']';
  }
  void operator()(const PixelsOp& p) const {
    if (const auto dot = as_rect(p)) {
      (*this)(*dot);
      return;
    }
    put_all(out, "\"P\",", p.area.x, ',', p.area.y, ',', p.area.width, ',', p.area.height, ',');
    if (block && *block)
      out += (*block)(p);
    else
      put_all(out, '"', frame_text::png_data_uri(p), '"');
  }
};

// A glyph's strokes as the "glyphs" table writes them, [[x,y,x,y,...],...]: the same few dozen
// glyphs in every frame, so each is written once per thread and kept (the explorer's module writes
// a frame per mouse move).
const std::string& glyph_strokes_json(const GlyphTable::Glyph& g) {
  thread_local std::map<std::tuple<unsigned char, int, double>, std::string> written;
  auto [at, added] = written.try_emplace({g.c, static_cast<int>(g.font), g.scale});
  if (added) {
    std::string out(1, '[');
    for (const auto& stroke : hershey_glyph_strokes(g.c, g.font, g.scale)) {
      if (out.size() > 1) out += ',';
      out += '[';
      put_points(out, stroke);
      out += ']';
    }
    out += ']';
    at->second = std::move(out);
  }
  return at->second;
}

void put_mark(std::string& out, const Mark& m) {
  put_all(out, "{\"kind\":\"", to_string(m.kind), "\",\"what\":", json_string(m.what), ",\"box\":",
          box(m.box), ",\"layer\":", m.layer, '}');
}

// One op appended to `out`, its text's glyphs (glyph_table) interned in `glyphs`; `b` is scratch
// space for its body (a frame's ops reuse one rather than allocate a string each).
void op_json(std::string& out, const DrawOp& op, TextForm text, GlyphTable* glyphs,
             const BlockWriter* block, std::string& b) {
  // The kind first, then clip and mark: written after the body's kind, as the format says.
  b.clear();
  std::visit(Writer{b, text, glyphs, block}, op.body);
  const std::size_t comma = b.find(',');
  out += '[';
  out.append(b, 0, comma);
  out += ',';
  out += op.clip ? box(*op.clip) : "null";
  out += ',';
  if (op.mark)
    put_mark(out, *op.mark);
  else
    out += "null";
  out.append(b, comma);
  out += ']';
}

// The strings of a frame's numbers (to_numbers): each once, by index, as a JSON array.
class StringTable {
 public:
  // Appends to `json` (an empty string): assigning a literal drew GCC 12's -Wrestrict false
  // positive here.
  explicit StringTable(std::string& json) : json_(json) { json_ += '['; }
  double operator()(const std::string& s) {
    const auto [at, added] = index_.try_emplace(s, static_cast<int>(index_.size()));
    if (added) put_all(json_, at->second ? "," : "", json_string(s));
    return at->second;
  }
  void close() { json_ += ']'; }

 private:
  std::string& json_;
  std::map<std::string, int> index_;
};

// Each op's arguments as the JSON writes them (Writer, glyph_table form), as numbers: the JSON's
// numbers as a reader of its text gets them (number_value), strings by their index.
struct NumberWriter {
  std::vector<double>& out;
  StringTable& strings;
  GlyphTable& glyphs;
  const NumberBlockWriter& block;
  void put(std::initializer_list<double> values) const { out.insert(out.end(), values); }
  void operator()(const RectOp& r) const {
    put({double(r.rect.x), double(r.rect.y), double(r.rect.width), double(r.rect.height),
         strings(hex_colour(r.colour)), double(r.thickness)});
  }
  void operator()(const LineOp& l) const {
    const double s = 1.0 / (1 << l.shift);
    put({frame_text::number_value(l.a.x * s), frame_text::number_value(l.a.y * s),
         frame_text::number_value(l.b.x * s), frame_text::number_value(l.b.y * s),
         strings(hex_colour(l.colour)), double(l.thickness)});
  }
  void operator()(const CircleOp& c) const {
    put({double(c.centre.x), double(c.centre.y), double(c.radius), strings(hex_colour(c.colour)),
         double(c.thickness)});
  }
  void operator()(const TextOp& t) const {
    const std::vector<PlacedGlyph> placed = hershey_layout(t.text, t.font, t.scale, t.origin);
    put({strings(t.text), strings(hex_colour(t.colour)), double(t.thickness), double(placed.size())});
    const double s = hershey_scale(t.scale);
    for (const PlacedGlyph& g : placed)
      put({double(glyphs.id(g.c, t.font, s)), frame_text::number_value(g.origin.x),
           frame_text::number_value(g.origin.y)});
  }
  void operator()(const PixelsOp& p) const {
    if (const auto dot = as_rect(p)) return (*this)(*dot);
    put({double(p.area.x), double(p.area.y), double(p.area.width), double(p.area.height)});
    block(p, out);
  }
};

// A glyph's strokes as to_numbers writes them (stroke count, then each stroke's count of numbers
// and its numbers), kept per thread as glyph_strokes_json keeps its text.
const std::vector<double>& glyph_strokes_numbers(const GlyphTable::Glyph& g) {
  thread_local std::map<std::tuple<unsigned char, int, double>, std::vector<double>> written;
  auto [at, added] = written.try_emplace({g.c, static_cast<int>(g.font), g.scale});
  if (added) {
    const auto strokes = hershey_glyph_strokes(g.c, g.font, g.scale);
    at->second.push_back(static_cast<double>(strokes.size()));
    for (const auto& stroke : strokes) {
      at->second.push_back(2.0 * static_cast<double>(stroke.size()));
      for (const Point2d& p : stroke) {
        at->second.push_back(frame_text::number_value(p.x));
        at->second.push_back(frame_text::number_value(p.y));
      }
    }
  }
  return at->second;
}

}  // namespace

std::string to_json(const DrawOp& op, TextForm text) {
  std::string out, body;
  op_json(out, op, text == TextForm::glyph_table ? TextForm::strokes : text, nullptr, nullptr, body);
  return out;
}

std::string to_json(const Frame& frame, TextForm text, const BlockWriter& block) {
  std::string out;
  put_all(out, "{\"w\":", frame.size().width, ",\"h\":", frame.size().height, ",\"bg\":\"",
          hex_colour(frame.background()), "\",\"ops\":[");
  GlyphTable glyphs;
  std::string body;
  bool first = true;
  for (const DrawOp& op : frame.ops()) {
    if (!first) out += ",\n";
    op_json(out, op, text, &glyphs, &block, body);
    first = false;
  }
  out += ']';
  if (text == TextForm::glyph_table) {
    out += ",\"glyphs\":[";
    for (std::size_t id = 0; id < glyphs.glyphs().size(); ++id) {
      out += id ? "," : "";
      out += glyph_strokes_json(glyphs.glyphs()[id]);
    }
    out += ']';
  }
  out += "}\n";
  return out;
}

NumberFrame to_numbers(const Frame& frame, const NumberBlockWriter& block) {
  NumberFrame f;
  StringTable strings(f.strings);
  GlyphTable glyphs;
  std::vector<double>& v = f.numbers;
  v.push_back(static_cast<double>(frame.ops().size()));
  f.marks += '[';
  double marks = 0;
  for (const DrawOp& op : frame.ops()) {
    const auto* pixels = std::get_if<PixelsOp>(&op.body);
    v.push_back(pixels && as_rect(*pixels) ? 0.0 : static_cast<double>(op.body.index()));
    if (op.clip)
      v.insert(v.end(), {1.0, double(op.clip->x), double(op.clip->y), double(op.clip->width),
                         double(op.clip->height)});
    else
      v.push_back(0);
    if (op.mark) {
      if (marks > 0) f.marks += ',';
      put_mark(f.marks, *op.mark);
      v.push_back(marks++);
    } else {
      v.push_back(-1);
    }
    std::visit(NumberWriter{v, strings, glyphs, block}, op.body);
  }
  f.marks += ']';
  strings.close();
  v.push_back(static_cast<double>(glyphs.glyphs().size()));
  for (const GlyphTable::Glyph& g : glyphs.glyphs()) {
    const std::vector<double>& strokes = glyph_strokes_numbers(g);
    v.insert(v.end(), strokes.begin(), strokes.end());
  }
  return f;
}

const char* frame_canvas_script() {
  return web_player::frame_draw_js;
}

}  // namespace scantrace::viz
