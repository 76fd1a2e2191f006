// The Hershey text layout in JavaScript, for a player that lays text out in the page rather than
// receiving placed glyphs (the Jupyter player: its deck carries each text op as a string, the
// course triangle's player 0.59 MB where placed glyphs would take it to 1.0, python/scantrace/
// player.js). The glyph table is the deck's (viz/hershey/glyphs.inc, the same strings the C++
// reads); the layout is viz::hershey_strokes' (viz/hershey.cpp), step for step:
// python/tests/test_player.py holds the two to 0.005 px over every text of a player.
// viz::hershey_strokes (viz/hershey.cpp) in the same floating-point steps: the strokes of `text`
// drawn from (x, y) on the baseline, as flat [x0, y0, x1, y1, ...] polylines.
export function scantraceHersheyStrokes(glyphs, text, scale, x0, y0) {
  const s = Math.round(scale * 65536) / 65536;
  const y = y0 - 9 * s;
  let x = x0;
  const strokes = [];
  for (const ch of text) {  // a code point: printable ASCII is itself, anything else '?'
    const g = glyphs[ch.length === 1 && ch >= ' ' && ch <= '~' ? ch : '?'];
    x -= (g.charCodeAt(0) - 82) * s;
    let stroke = [];
    for (let p = 2; p + 1 < g.length; p += 2) {
      if (g[p] === ' ' && g[p + 1] === 'R') {  // pen up
        if (stroke.length > 2) strokes.push(stroke);
        stroke = [];
        continue;
      }
      stroke.push(x + (g.charCodeAt(p) - 82) * s, y + (g.charCodeAt(p + 1) - 82) * s);
    }
    if (stroke.length > 2) strokes.push(stroke);
    x += (g.charCodeAt(1) - 82) * s;
  }
  return strokes;
}
