#pragma once
// A replay's frames as one compact JSON "deck" for the inline Jupyter player
// (python/scantrace/_player.py, drawn by player.js on a <canvas> through the canvas backend's
// drawScantraceFrame, viz/frame_json.hpp). Frames of one replay repeat most of their operations
// (title bar, legend, grid, labels that stay), and a text's Hershey strokes are ~95 % of a frame's
// canvas JSON, so the deck keeps every distinct operation once and draws text from the glyphs:
//
//   {"w": W, "h": H, "bg": "#rrggbb",
//    "glyphs": {"0": {"A": "<Hershey glyph>", ...}, "2": {...}},   fonts by OpenCV number
//    "ops": [OP, ...],               every distinct operation, in order of first use
//    "frames": [[start, count, start, count, ...], ...],   a frame: runs of op indices
//    "labels": ["scanline y = 80 (61 of 380)", ...],        one line per step (viz/step_label)
//    "rows": [null, [80, 80], ...]}                       the scanlines a step shows, or null
//
// An OP is the canvas JSON's (frame_json.hpp: [kind, clip, mark, ...]) except text, which is
//   ["t", clip, mark, text, colour, thickness, font, scale, x, y]   (origin on the baseline)
// and which player.js turns back into the canvas JSON's "T" op with the strokes
// viz::hershey_strokes computes (the same arithmetic on the same glyphs).
#include <cstddef>
#include <string>

#include "viz/frame_sequence.hpp"

namespace scantrace::python {

struct Deck {
  std::string json;
  std::size_t frames = 0;
  std::size_t distinct_ops = 0;
};

// Steps first..last (0-based, inclusive) of `frames` as a deck.
Deck write_deck(viz::FrameSequence& frames, std::size_t first, std::size_t last);

}  // namespace scantrace::python
