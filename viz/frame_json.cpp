#include "viz/frame_json.hpp"

#include <cstdio>
#include <map>
#include <tuple>

#include <spdlog/fmt/fmt.h>

#include "viz/frame_text.hpp"
#include "viz/glyph_table.hpp"

namespace scantrace::viz {
namespace {

using frame_text::hex_colour;
using frame_text::json_string;
using frame_text::number;

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
    put_all(out, i ? "," : "", number(stroke[i].x), ',', number(stroke[i].y));
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
    put_all(out, "\"L\",", number(l.a.x * s), ',', number(l.a.y * s), ',', number(l.b.x * s), ',',
            number(l.b.y * s), ",\"", hex_colour(l.colour), "\",", l.thickness);
  }
  void operator()(const CircleOp& c) const {
    put_all(out, "\"C\",", c.centre.x, ',', c.centre.y, ',', c.radius, ",\"", hex_colour(c.colour),
            "\",", c.thickness);
  }
  void operator()(const TextOp& t) const {
    if (text_form == TextForm::glyphs) {
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
        put_all(out, first ? "" : ",", glyphs->id(g.c, t.font, s), ',', number(g.origin.x), ',',
                number(g.origin.y));
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
    if (p.area.area() == 1) {  // a grid's centre dot: a filled rectangle, not an image
      const Vec3b& c = p.bgr->front();
      (*this)(RectOp{p.area, Scalar(c[0], c[1], c[2]), FILLED});
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
// glyphs in every frame, so each is written once per thread and kept (their numbers were a fifth
// of a step frame's JSON time in the explorer's module, which writes a frame per mouse move).
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

// One op appended to `out`, its text's glyphs (glyph_table) interned in `glyphs`; `b` is scratch
// space for its body (a frame's ops reuse one: a string per op was a sixth of the JSON's time).
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
    put_all(out, "{\"kind\":\"", to_string(op.mark->kind), "\",\"what\":", json_string(op.mark->what),
            ",\"box\":", box(op.mark->box), ",\"layer\":", op.mark->layer, '}');
  else
    out += "null";
  out.append(b, comma);
  out += ']';
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

const char* frame_canvas_script() {
  // Coordinates are OpenCV's (pixel centres on integers): strokes are drawn half a pixel right and
  // down, filled rectangles and pixel blocks over the pixels they cover, as the SVG backend does.
  return R"JS(function drawScantraceFrame(ctx, frame) {
  // A pixel block is a PNG data URI, which loads asynchronously (load them all, then draw every
  // op in order), or its RGBA bytes {width, height, data} (the WebAssembly module's frames with
  // blocks: 'rgba'), drawn at once: a frame of those is drawn before this returns.
  const blocks = frame.ops.filter((op) => op[0] === 'P' && typeof op[7] === 'string').map((op) => new Promise((ok, fail) => {
    const img = new Image();
    img.onload = () => ok(img);
    img.onerror = fail;
    img.src = op[7];
  }));
  const draw = (images) => {
    let k = 0;
    // putImageData ignores the context's transform: an RGBA block goes through it only on an
    // untransformed context (the explorer's), else through a canvas of its own and drawImage.
    const untransformed = ctx.getTransform().isIdentity;
    // One save for the frame (the caller's context comes back as it was), and one more only
    // around an op with a clip: every op sets the colours and widths it draws with, and a save
    // and restore for each of a step frame's ~800 ops was a fifth of drawing it in Chromium.
    ctx.save();
    ctx.fillStyle = frame.bg;
    ctx.fillRect(0, 0, frame.w, frame.h);
    ctx.lineCap = 'round';
    ctx.lineJoin = 'round';
    for (const op of frame.ops) {
      const [kind, clip] = op;
      // The op's arguments from index 3 (a copy of them per op, op.slice(3), was a tenth of
      // drawing a step frame's ~800 ops).
      if (clip) {
        ctx.save();
        ctx.beginPath();
        ctx.rect(clip[0], clip[1], clip[2], clip[3]);
        ctx.clip();
        ctx.translate(clip[0], clip[1]);
      }
      if (kind === 'R') {
        const x = op[3], y = op[4], w = op[5], h = op[6], c = op[7], t = op[8];
        if (t < 0) {
          ctx.fillStyle = c;
          ctx.fillRect(x, y, w, h);
        } else {
          ctx.strokeStyle = c;
          ctx.lineWidth = t;
          ctx.strokeRect(x + 0.5, y + 0.5, w - 1, h - 1);
        }
      } else if (kind === 'L') {
        const x1 = op[3], y1 = op[4], x2 = op[5], y2 = op[6], c = op[7], t = op[8];
        ctx.strokeStyle = c;
        ctx.lineWidth = t;
        ctx.beginPath();
        ctx.moveTo(x1 + 0.5, y1 + 0.5);
        ctx.lineTo(x2 + 0.5, y2 + 0.5);
        ctx.stroke();
      } else if (kind === 'C') {
        const x = op[3], y = op[4], r = op[5], c = op[6], t = op[7];
        ctx.beginPath();
        ctx.arc(x + 0.5, y + 0.5, t < 0 ? r + 0.5 : r, 0, 2 * Math.PI);
        if (t < 0) {
          ctx.fillStyle = c;
          ctx.fill();
        } else {
          ctx.strokeStyle = c;
          ctx.lineWidth = t;
          ctx.stroke();
        }
      } else if (kind === 'T') {
        const c = op[4], t = op[5], strokes = op[6];
        ctx.strokeStyle = c;
        ctx.lineWidth = t;
        ctx.beginPath();
        for (const s of strokes) {
          ctx.moveTo(s[0] + 0.5, s[1] + 0.5);
          for (let i = 2; i < s.length; i += 2) ctx.lineTo(s[i] + 0.5, s[i + 1] + 0.5);
        }
        ctx.stroke();
      } else if (kind === 'G') {
        // Glyphs placed from the frame's table: each stroke point is the glyph's origin plus its
        // point in the table (what the strokes of a 'T' op hold, summed here).
        const c = op[4], t = op[5], placed = op[6];
        ctx.strokeStyle = c;
        ctx.lineWidth = t;
        ctx.beginPath();
        for (let g = 0; g < placed.length; g += 3) {
          const x = placed[g + 1] + 0.5, y = placed[g + 2] + 0.5;
          for (const s of frame.glyphs[placed[g]]) {
            ctx.moveTo(x + s[0], y + s[1]);
            for (let i = 2; i < s.length; i += 2) ctx.lineTo(x + s[i], y + s[i + 1]);
          }
        }
        ctx.stroke();
      } else if (kind === 'P' && typeof op[7] === 'string') {
        ctx.imageSmoothingEnabled = false;
        ctx.drawImage(images[k++], op[3], op[4]);
      } else if (kind === 'P' && op[7].cols) {
        // Runs of equal columns and rows and one texel each ({width, height, cols, rows, texels}:
        // the WebAssembly module's magnified cells): the texels stretched over each column run
        // into one row per row run, then each of those rows stretched over its run's height. A
        // source one texel wide or one row tall is sampled at that texel whatever the scale, so
        // this draws the block's own pixels, as putImageData of the whole block would.
        const b = op[7], n = b.rows.length, row = new Uint32Array(b.width * n);
        const texel = new Uint32Array(b.texels.buffer, b.texels.byteOffset, b.cols.length * n);
        // A plain loop: runs are a few pixels wide, and a fill() per run cost more than its pixels.
        for (let r = 0, i = 0, t = 0; r < n; ++r)
          for (let c = 0; c < b.cols.length; ++c, ++t)
            for (let k = b.cols[c], v = texel[t]; k > 0; --k) row[i++] = v;
        // One strip canvas kept for every frame (a new canvas per frame cost more than its
        // pixels); putImageData replaces all of its pixels.
        const strip = drawScantraceFrame.strip || (drawScantraceFrame.strip = document.createElement('canvas'));
        if (strip.width !== b.width || strip.height !== n) {
          strip.width = b.width;
          strip.height = n;
        }
        strip.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(row.buffer), b.width, n), 0, 0);
        ctx.imageSmoothingEnabled = false;
        for (let r = 0, y = op[4]; r < n; y += b.rows[r++]) ctx.drawImage(strip, 0, r, b.width, 1, op[3], y, b.width, b.rows[r]);
      } else if (kind === 'P' && !untransformed) {
        const b = op[7], c = document.createElement('canvas');
        c.width = b.width;
        c.height = b.height;
        c.getContext('2d').putImageData(new ImageData(b.data, b.width, b.height), 0, 0);
        ctx.imageSmoothingEnabled = false;
        ctx.drawImage(c, op[3], op[4]);
      } else if (kind === 'P') {
        // putImageData ignores the clip too: the clip's corner and the clip itself (as the
        // block's dirty rectangle) applied here.
        const b = op[7], ox = clip ? clip[0] : 0, oy = clip ? clip[1] : 0;
        const dx = clip ? Math.max(0, -op[3]) : 0, dy = clip ? Math.max(0, -op[4]) : 0;
        const dw = (clip ? Math.min(b.width, clip[2] - op[3]) : b.width) - dx;
        const dh = (clip ? Math.min(b.height, clip[3] - op[4]) : b.height) - dy;
        if (dw > 0 && dh > 0)
          ctx.putImageData(new ImageData(b.data, b.width, b.height), ox + op[3], oy + op[4], dx, dy, dw, dh);
      }
      if (clip) ctx.restore();
    }
    ctx.restore();
  };
  if (!blocks.length) {
    draw([]);
    return Promise.resolve();
  }
  return Promise.all(blocks).then(draw);
}
)JS";
}

}  // namespace scantrace::viz
