#pragma once
// The canvas backend's half on this side (docs/design.md §6): a display list as compact JSON for
// a browser, drawn on an HTML <canvas> by the JavaScript of frame_canvas_script().
//
//   {"w": 1280, "h": 720, "bg": "#f6f6f6", "ops": [OP, ...]}
//
// Every OP is an array [kind, clip, mark, ...]: clip null or [x, y, w, h] (the op's coordinates
// are then relative to that area's corner and it draws nothing outside it), mark null or
// {"kind", "what", "box": [x, y, w, h], "layer"} (absolute box). Coordinates are OpenCV's: a
// pixel's centre on integers.
//   ["R", clip, mark, x, y, w, h, colour, thickness]   thickness -1: filled
//   ["L", clip, mark, x1, y1, x2, y2, colour, thickness]   end points in pixels (subpixel)
//   ["C", clip, mark, cx, cy, radius, colour, thickness]   thickness -1: a disc
//   ["T", clip, mark, text, colour, thickness, [[x, y, x, y, ...], ...]]   the Hershey strokes
//   ["G", clip, mark, text, colour, thickness, [id, x, y, id, x, y, ...]]   the same text as its
//       glyphs placed (TextForm::glyph_table): glyph `id` of the frame's "glyphs" with its origin
//       at (x, y); a stroke point is that origin plus the glyph's point
//   ["P", clip, mark, x, y, w, h, "data:image/png;base64,..."]   a block of pixels
// (drawScantraceFrame also takes the block as {width, height, data}, its RGBA bytes, or as
// {width, height, cols, rows, texels}, its runs of equal columns and rows and one RGBA texel per
// run pair, in place of the data URI: the WebAssembly module's frames with blocks: 'rgba', drawn
// without loading)
// With TextForm::glyph_table the frame also holds
//   "glyphs": [[[dx, dy, dx, dy, ...], ...], ...]   glyph id's strokes relative to its origin
// each glyph (character, font and scale) written once however often the frame's text repeats it
// (viz/glyph_table.hpp): a tenth of the strokes' JSON for a step frame.
// Colours are "#rrggbb". Text comes as its strokes, so the browser needs no font and draws the
// glyphs the composer measured.
#include <functional>
#include <string>
#include <vector>

#include "viz/frame.hpp"

namespace scantrace::viz {

// How text is written: `strokes`, its strokes ("T"); `glyph_table`, its glyphs placed from the
// frame's glyph table ("G", whole frames only); or `text_with_font`, for one op, the text itself
// with what lays it out:
//   ["t", clip, mark, text, colour, thickness, font, scale, x, y]   (font: OpenCV's number; the
// scale with 17 digits; origin on the baseline), for a reader that holds the Hershey glyphs and
// repeats hershey_strokes() (the Jupyter player's deck, python/src/player_deck.hpp: strokes are
// ~95 % of a frame's JSON).
enum class TextForm { strokes, text_with_font, glyph_table };

// A pixel block's last element, as JSON (by default the PNG data URI as a string): the
// WebAssembly module writes the offset of its RGBA bytes instead (web/bindings_trace.cpp).
using BlockWriter = std::function<std::string(const PixelsOp&)>;

std::string to_json(const Frame& frame, TextForm text = TextForm::strokes,
                    const BlockWriter& block = {});

// One OP of the list above (text as strokes or "t"; glyph_table needs the whole frame).
std::string to_json(const DrawOp& op, TextForm text = TextForm::strokes);

// The same display list as numbers, for a page that reads them with a Float64Array instead of
// parsing JSON (the WebAssembly module's frames with encoding: 'binary'; web/scantrace.mjs reads
// them back into the frame JSON.parse would give, its numeric lists as typed arrays). Every number
// is the one a reader of to_json's text gets (frame_text::number_value); strings and marks are
// apart, as JSON arrays, referred to by index. Text as its glyphs placed from the frame's table
// (TextForm::glyph_table). The numbers:
//   the op count; for each op its kind (0 "R", 1 "L", 2 "C", 3 "G", 4 "P"), its clip (0, or 1
//   and x, y, w, h), its mark's index (-1: none), then its arguments as the JSON's, a string by
//   its index: R x y w h colour thickness; L x1 y1 x2 y2 colour thickness; C cx cy radius colour
//   thickness; G text colour thickness n, then n times id x y; P x y w h, then what `block`
//   appends;
//   then the glyph count, and for each glyph its stroke count and for each stroke its count of
//   numbers and the numbers (dx, dy, ...).
struct NumberFrame {
  std::vector<double> numbers;
  std::string strings;  // ["#ffffff", "scanline 61 of 380", ...]
  std::string marks;    // [{"kind", "what", "box", "layer"}, ...]
};
using NumberBlockWriter = std::function<void(const PixelsOp&, std::vector<double>&)>;
NumberFrame to_numbers(const Frame& frame, const NumberBlockWriter& block);

// `drawScantraceFrame(ctx, frame)`: draws a parsed to_json() frame on a 2D canvas context of the
// frame's size; returns a Promise that resolves when the pixel blocks (images) are drawn too.
// tests/viz/test_canvas_frame.cpp runs it in headless Chromium against the OpenCV raster.
const char* frame_canvas_script();

}  // namespace scantrace::viz
