// Redraws a step's frame over the one drawn before it, only where they differ (the explorer's
// vertex drag: between two mouse moves the title, the legend, the edge table's unchanged rows and
// the panel's fixed text stay as they were; drawing every op again was a third of a move,
// docs/performance.md).
//
// The ops of the two frames are matched in order by what they draw (a "G" op's glyphs by their
// strokes, not their ids: a frame's glyph table numbers glyphs in order of first use). Every op
// left unmatched, old or new, and every pixel block (the cells, which a move changes anyway)
// marks its box dirty; the dirty boxes are cleared to the background and every op of the new frame
// whose box meets one is drawn again in order, clipped to them. A pixel outside them is covered
// only by matched ops, drawn in the same order on the same background as before, so the canvas is
// the frame drawn whole (the page's test compares the two after a drag).

// Pixels around an op's geometry that its drawing may touch: half the line width, the half-pixel
// offset of the canvas backend's strokes, round caps and antialiasing.
const pad = (thickness) => Math.ceil(Math.max(0, thickness)) + 2;

function glyphBounds(strokes) {
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (const s of strokes)
    for (let i = 0; i < s.length; i += 2) {
      x0 = Math.min(x0, s[i]);
      x1 = Math.max(x1, s[i]);
      y0 = Math.min(y0, s[i + 1]);
      y1 = Math.max(y1, s[i + 1]);
    }
  return [x0, y0, x1, y1];
}

// The op's box on the frame, [x0, y0, x1, y1] in whole pixels (x1, y1 excluded), inside its clip.
function opBox(op, glyphs) {
  const [kind, clip] = op;
  const a = op.slice(3);
  let b;
  if (kind === 'R' || kind === 'P') b = [a[0], a[1], a[0] + a[2], a[1] + a[3], kind === 'R' ? a[5] : 0];
  else if (kind === 'L') b = [Math.min(a[0], a[2]), Math.min(a[1], a[3]), Math.max(a[0], a[2]), Math.max(a[1], a[3]), a[5]];
  else if (kind === 'C') b = [a[0] - a[2], a[1] - a[2], a[0] + a[2], a[1] + a[2], a[4]];
  else if (kind === 'T' || kind === 'G') {
    b = [Infinity, Infinity, -Infinity, -Infinity, a[2]];
    const extend = (x0, y0, x1, y1) => {
      b[0] = Math.min(b[0], x0);
      b[1] = Math.min(b[1], y0);
      b[2] = Math.max(b[2], x1);
      b[3] = Math.max(b[3], y1);
    };
    if (kind === 'T') for (const s of a[3]) for (let i = 0; i < s.length; i += 2) extend(s[i], s[i + 1], s[i], s[i + 1]);
    else
      for (let g = 0; g < a[3].length; g += 3) {
        const [x0, y0, x1, y1] = glyphs[a[3][g]];
        extend(a[3][g + 1] + x0, a[3][g + 2] + y0, a[3][g + 1] + x1, a[3][g + 2] + y1);
      }
  } else return null; // unknown: the whole frame redrawn
  const p = pad(b[4]);
  const [ox, oy] = clip ? [clip[0], clip[1]] : [0, 0];
  let box = [Math.floor(ox + b[0] - p), Math.floor(oy + b[1] - p), Math.ceil(ox + b[2] + p + 1), Math.ceil(oy + b[3] + p + 1)];
  if (clip) box = [Math.max(box[0], clip[0]), Math.max(box[1], clip[1]), Math.min(box[2], clip[0] + clip[2]), Math.min(box[3], clip[1] + clip[3])];
  return box;
}

// What an op draws, as a string; null for a pixel block (always redrawn).
function opKey(op, glyphKeys) {
  if (op[0] === 'P') return null;
  if (op[0] !== 'G') return JSON.stringify(op);
  const placed = op[6];
  let key = JSON.stringify(op.slice(0, 6));
  for (let g = 0; g < placed.length; g += 3) key += `|${glyphKeys[placed[g]]}@${placed[g + 1]},${placed[g + 2]}`;
  return key;
}

const meets = (a, b) => a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];

// Rectangles covering the same pixels as `rects`, none overlapping another: overlapping ones
// merged into their bounding box until none overlap (each pixel then redrawn once).
function disjoint(rects) {
  const out = [];
  for (let r of rects) {
    for (let i = 0; i < out.length; ++i)
      if (meets(out[i], r)) {
        r = [Math.min(r[0], out[i][0]), Math.min(r[1], out[i][1]), Math.max(r[2], out[i][2]), Math.max(r[3], out[i][3])];
        out.splice(i, 1);
        i = -1; // the grown rectangle may now meet one seen before
      }
    out.push(r);
  }
  return out;
}

// frameRedraw(drawScantraceFrame) → draw(ctx, frame): draws `frame` on an untransformed context
// whose canvas holds the frame the last call drew (the whole frame on the first call, after
// reset(), or when the size, background or kind of blocks does not allow the shortcut).
// The dirty rectangles grown until each holds the whole box of every op it meets, then made
// disjoint: an antialiased stroke cut by a clip's edge came out a unit or so off where it was
// drawn (Skia clips the stroke's geometry first). Filled rectangles and pixel blocks are exempt:
// whole pixels, which a clip cannot change, and the panels' backgrounds, which would otherwise
// pull in the whole panel.
function closed(dirty, ops, boxes) {
  const cuttable = ops.map((op) => !((op[0] === 'R' && op[8] < 0) || op[0] === 'P'));
  let rects = disjoint(dirty);
  for (let grown = true; grown;) {
    grown = false;
    rects = disjoint(rects.map((d) => {
      for (let i = 0; i < boxes.length; ++i) {
        const b = boxes[i];
        if (!cuttable[i] || !meets(b, d) || (b[0] >= d[0] && b[1] >= d[1] && b[2] <= d[2] && b[3] <= d[3])) continue;
        d = [Math.min(d[0], b[0]), Math.min(d[1], b[1]), Math.max(d[2], b[2]), Math.max(d[3], b[3])];
        grown = true;
      }
      return d;
    }));
  }
  return rects;
}

export function frameRedraw(drawFrame) {
  let last = null; // {w, h, bg, keys, boxes}
  const draw = (ctx, frame) => {
    const glyphs = (frame.glyphs || []).map(glyphBounds);
    const glyphKeys = (frame.glyphs || []).map((g) => JSON.stringify(g));
    const keys = frame.ops.map((op) => opKey(op, glyphKeys));
    const boxes = frame.ops.map((op) => opBox(op, glyphs));
    const whole = !last || last.w !== frame.w || last.h !== frame.h || last.bg !== frame.bg ||
      !ctx.getTransform().isIdentity || boxes.includes(null) ||
      // A block of RGBA bytes is put with putImageData, which no clip holds back.
      frame.ops.some((op) => op[0] === 'P' && !(op[7] && op[7].cols));
    if (whole) {
      drawFrame(ctx, frame);
    } else {
      // Match in order: each new op to the next old op that draws the same, after the last match.
      const unmatchedOld = new Set(last.keys.keys());
      const where = new Map();
      last.keys.forEach((k, i) => {
        if (k === null) return;
        if (!where.has(k)) where.set(k, []);
        where.get(k).push(i);
      });
      const dirty = [];
      let after = -1;
      keys.forEach((k, i) => {
        const list = k === null ? null : where.get(k);
        const j = list ? list.find((o) => o > after) : undefined;
        if (j === undefined) {
          dirty.push(boxes[i]);
          return;
        }
        after = j;
        unmatchedOld.delete(j);
      });
      for (const j of unmatchedOld) dirty.push(last.boxes[j]);
      // One rectangle clip at a time: Chromium's clip to a path of hundreds of overlapping
      // rectangles changed antialiased pixels inside it (by up to 10 of 255).
      for (const d of closed(dirty.filter((r) => r[0] < r[2] && r[1] < r[3]), frame.ops, boxes)) {
        ctx.save();
        ctx.beginPath();
        ctx.rect(d[0], d[1], d[2] - d[0], d[3] - d[1]);
        ctx.clip();
        drawFrame(ctx, { ...frame, ops: frame.ops.filter((op, i) => meets(boxes[i], d)) });
        ctx.restore();
      }
    }
    last = { w: frame.w, h: frame.h, bg: frame.bg, keys, boxes };
  };
  draw.reset = () => {
    last = null;
  };
  return draw;
}
