// drawScantraceFrame(ctx, frame): the canvas backend of the display list (viz/frame_json.hpp's
// canvas JSON) and its helpers, a classic script (global functions): pages inline it, the
// WebAssembly modules and Python return it (frame_canvas_script(), embedded at build time by
// cmake/web_player.cmake). Coordinates are OpenCV's (pixel centres on integers): strokes are
// drawn half a pixel right and down, filled rectangles and pixel blocks over the pixels they
// cover, as the SVG backend does.
function drawScantraceFrame(ctx, frame) {
  // A pixel block is a PNG data URI, which loads asynchronously (load them all, then draw every
  // op in order), or its RGBA bytes {width, height, data} (the WebAssembly module's frames with
  // blocks: 'rgba'), drawn at once: a frame of those is drawn before this returns.
  const blocks = frame.ops.filter((op) => op[0] === 'P' && typeof op[7] === 'string').map((op) => new Promise((ok, fail) => {
    const img = new Image();
    img.onload = () => ok(img);
    img.onerror = fail;
    img.src = op[7];
  }));
  if (!blocks.length) {
    scantraceDrawOps(ctx, frame, []);
    return Promise.resolve();
  }
  return Promise.all(blocks).then((images) => scantraceDrawOps(ctx, frame, images));
}

// A run of filled rectangles of one colour (a step frame's 518 are in 40 runs, most of them a
// grid's centre dots) is one path where the context draws in whole pixels: rectangles on whole
// pixels cover the same pixels filled together or one by one (a rectangle a call was 0.7 ms of a
// frame, recorded and rasterised).
function scantraceSameFill(o, c) {
  return o && o[0] === 'R' && !o[1] && o[8] < 0 && o[7] === c;
}

// Consecutive ops of one clip are drawn under one save, clip and restore (a step frame's 172
// clipped ops are in 10 such groups): each op sets what it draws with, so an op draws the same
// pixels after another of its group as alone, and a save, clip and restore an op was a tenth of
// drawing the frame in Chromium.
function scantraceSameClip(a, b) {
  return a === b || (!!a && !!b && a[0] === b[0] && a[1] === b[1] && a[2] === b[2] && a[3] === b[3]);
}

// The frame's ops in order, the PNG blocks' `images` loaded.
function scantraceDrawOps(ctx, frame, images) {
  // putImageData ignores the context's transform: an RGBA block goes through it only on an
  // untransformed context (the explorer's), else through a canvas of its own and drawImage.
  const transform = ctx.getTransform(), untransformed = transform.isIdentity;
  // Text ops from bitmaps kept between frames (scantraceTextBitmaps, below) where the context
  // draws in its canvas's pixels or scales them without turning (the trace page's); elsewhere
  // stroked as they come.
  const text = untransformed || (!transform.b && !transform.c && transform.a > 0 && transform.d > 0)
    ? (drawScantraceFrame.text || (drawScantraceFrame.text = scantraceTextBitmaps())).frame(frame)
    : null;
  const state = { ctx, frame, images, next: 0, untransformed, text };
  // One save for the frame (the caller's context comes back as it was), and one more only
  // around an op with a clip: every op sets the colours and widths it draws with, and a save
  // and restore for each of a step frame's ~800 ops was a fifth of drawing it in Chromium.
  ctx.save();
  ctx.fillStyle = frame.bg;
  ctx.fillRect(0, 0, frame.w, frame.h);
  ctx.lineCap = 'round';
  ctx.lineJoin = 'round';
  const ops = frame.ops;
  let clipped = null;
  for (let n = 0; n < ops.length; ++n) {
    const clip = ops[n][1];
    if (!scantraceSameClip(clip, clipped)) {
      if (clipped) ctx.restore();
      clipped = clip;
      if (clip) {
        ctx.save();
        ctx.beginPath();
        ctx.rect(clip[0], clip[1], clip[2], clip[3]);
        ctx.clip();
        ctx.translate(clip[0], clip[1]);
      }
    }
    n = scantraceDrawOp(state, ops, n, clip);
  }
  if (clipped) ctx.restore();
  ctx.restore();
}

// Op `n` of `ops` (and the run of rectangles it starts); returns the index of the last op drawn.
// The op's arguments are read from index 3 (a copy of them per op, op.slice(3), was a tenth of
// drawing a step frame's ~800 ops).
function scantraceDrawOp(state, ops, n, clip) {
  const ctx = state.ctx, op = ops[n], kind = op[0];
  if (kind === 'R') {
    const x = op[3], y = op[4], w = op[5], h = op[6], c = op[7], t = op[8];
    if (t < 0 && state.untransformed && !clip && scantraceSameFill(ops[n + 1], c)) {
      ctx.fillStyle = c;
      ctx.beginPath();
      ctx.rect(x, y, w, h);
      for (let o = ops[n + 1]; scantraceSameFill(o, c); o = ops[++n + 1]) ctx.rect(o[3], o[4], o[5], o[6]);
      ctx.fill();
    } else if (t < 0) {
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
    scantraceDrawCircle(ctx, op);
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
  } else if (kind === 'G' && state.text) {
    state.text.draw(ctx, op);
  } else if (kind === 'G') {
    ctx.strokeStyle = op[4];
    ctx.lineWidth = op[5];
    scantraceStrokeGlyphs(ctx, state.frame.glyphs, op[6], 0.5, 0.5);
  } else if (kind === 'P') {
    scantraceDrawBlock(state, op, clip);
  }
  return n;
}

function scantraceDrawCircle(ctx, op) {
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
}

// A "P" op: a loaded PNG, runs of texels, or RGBA bytes.
function scantraceDrawBlock(state, op, clip) {
  const ctx = state.ctx;
  if (typeof op[7] === 'string') {
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(state.images[state.next++], op[3], op[4]);
  } else if (op[7].cols && !(state.untransformed && scantraceOpaque(op[7].texels))) {
    scantraceDrawRuns(ctx, op);
  } else if (!state.untransformed) {
    const b = op[7], c = document.createElement('canvas');
    c.width = b.width;
    c.height = b.height;
    c.getContext('2d').putImageData(new ImageData(b.data, b.width, b.height), 0, 0);
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(c, op[3], op[4]);
  } else {
    // An RGBA block, or opaque runs spelled out into one (scantraceRunsPixels): a drag's frame
    // put its runs' rows with a drawImage each (65 of them), which cost three times putting
    // the whole blocks' pixels. putImageData ignores the clip too: the clip's corner and the
    // clip itself (as the block's dirty rectangle) applied here.
    const b = op[7].cols ? scantraceRunsPixels(op[7]) : op[7], ox = clip ? clip[0] : 0, oy = clip ? clip[1] : 0;
    const dx = clip ? Math.max(0, -op[3]) : 0, dy = clip ? Math.max(0, -op[4]) : 0;
    const dw = (clip ? Math.min(b.width, clip[2] - op[3]) : b.width) - dx;
    const dh = (clip ? Math.min(b.height, clip[3] - op[4]) : b.height) - dy;
    if (dw > 0 && dh > 0)
      ctx.putImageData(new ImageData(b.data, b.width, b.height), ox + op[3], oy + op[4], dx, dy, dw, dh);
  }
}

// Runs of equal columns and rows and one texel each ({width, height, cols, rows, texels}: the
// WebAssembly module's magnified cells) on a scaled context, or with a texel not opaque (drawn
// over what is below it): the texels stretched over each column run into one row per row run,
// then each of those rows stretched over its run's height. A source one texel wide or one row
// tall is sampled at that texel whatever the scale, so this draws the block's own pixels, as
// putImageData of the whole block would.
function scantraceDrawRuns(ctx, op) {
  const b = op[7], n = b.rows.length, row = new Uint32Array(b.width * n);
  const texel = new Uint32Array(b.texels.buffer, b.texels.byteOffset, b.cols.length * n);
  // A plain loop: runs are a few pixels wide, and a fill() per run cost more than its pixels.
  for (let r = 0, i = 0, t = 0; r < n; ++r)
    for (let c = 0; c < b.cols.length; ++c, ++t)
      for (let k = b.cols[c], v = texel[t]; k > 0; --k) row[i++] = v;
  // One strip canvas kept for every frame (a new canvas per frame cost more than its pixels);
  // putImageData replaces all of its pixels.
  const strip = drawScantraceFrame.strip || (drawScantraceFrame.strip = document.createElement('canvas'));
  if (strip.width !== b.width || strip.height !== n) {
    strip.width = b.width;
    strip.height = n;
  }
  strip.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(row.buffer), b.width, n), 0, 0);
  ctx.imageSmoothingEnabled = false;
  for (let r = 0, y = op[4]; r < n; y += b.rows[r++]) ctx.drawImage(strip, 0, r, b.width, 1, op[3], y, b.width, b.rows[r]);
}

// Whether every texel of RGBA bytes is opaque.
function scantraceOpaque(texels) {
  for (let i = 3; i < texels.length; i += 4) if (texels[i] !== 255) return false;
  return true;
}

// A block of runs ({width, height, cols, rows, texels}) as its RGBA pixels {width, height,
// data}: each row run's first row spelled out from its texels, the run's other rows copies of it.
// The pixels are written into one buffer kept for every block drawn (a new one per block was
// garbage to collect on every mouse move): good until the next block is spelled out.
function scantraceRunsPixels(b) {
  const size = b.width * b.height * 4;
  let keep = scantraceRunsPixels.keep;
  if (!keep || keep.length < size) keep = scantraceRunsPixels.keep = new Uint8ClampedArray(Math.max(size, 2 * (keep ? keep.length : 0)));
  const data = size === keep.length ? keep : new Uint8ClampedArray(keep.buffer, 0, size);
  const out = new Uint32Array(keep.buffer, 0, b.width * b.height);
  const texel = new Uint32Array(b.texels.buffer, b.texels.byteOffset, b.cols.length * b.rows.length);
  const w = b.width, cols = b.cols;
  for (let r = 0, y = 0, t = 0; r < b.rows.length; y += b.rows[r++]) {
    // A plain loop: runs are a few pixels wide, and a fill() per run cost more than its pixels.
    for (let c = 0, i = y * w; c < cols.length; ++c, ++t) for (let k = cols[c], v = texel[t]; k > 0; --k) out[i++] = v;
    for (let k = 1; k < b.rows[r]; ++k) out.copyWithin((y + k) * w, y * w, (y + 1) * w);
  }
  return { width: b.width, height: b.height, data };
}

// A "G" op's glyphs as one path, stroked with the context's colour and width: each stroke point
// is its glyph's origin plus (ox, oy) plus its point in the frame's table.
function scantraceStrokeGlyphs(ctx, glyphs, placed, ox, oy) {
  ctx.beginPath();
  for (let g = 0; g < placed.length; g += 3) {
    const x = placed[g + 1] + ox, y = placed[g + 2] + oy;
    for (const s of glyphs[placed[g]]) {
      ctx.moveTo(x + s[0], y + s[1]);
      for (let i = 2; i < s.length; i += 2) ctx.lineTo(x + s[i], y + s[i + 1]);
    }
  }
  ctx.stroke();
}

// Text ops ("G") drawn from bitmaps kept between frames (docs/design.md §6, "Text"). Stroking a
// step frame's 1,456 glyphs (27,550 points) was two thirds of drawing it in Chromium's software
// raster, and a mouse move of the explorer's drag leaves most labels as they were. Each op is
// stroked once, as one path as above, onto a canvas of its own at the op's phase (the fraction
// of a pixel of its first glyph's origin), then put on the frame with drawImage at whole pixels.
// Keyed by everything that decides its pixels: the colour, the width, the phase, and each glyph's
// strokes and offset from the first glyph, compared exactly (a hash only finds the candidates),
// so a frame of another size, scale or colour never takes another's bitmap. Bounded: at most
// `limit` bitmaps of `maxArea` pixels in all, the least recently drawn dropped first. (Per-glyph
// bitmaps measured slower: a drawImage per glyph cost more than its strokes.)
function scantraceTextBitmaps(limit = 256, maxArea = 1 << 22) {
  const st = {
    limit, maxArea,
    glyphs: new Map(), // hash of its strokes -> [{strokes, id, box}]
    ops: new Map(), // hash of the key -> [bitmap]
    recent: new Set(), // bitmaps, least recently drawn first
    spare: new Map(), // width * 65536 + height -> canvases of dropped bitmaps, reused
    stats: { hits: 0, misses: 0, bitmaps: 0, area: 0, glyphs: 0, spare: 0 },
    nextGlyph: 0,
  };
  // What a frame's ops draw with: draw(ctx, op) puts a "G" op's bitmap, made if missing.
  const frame = (f) => {
    const seen = [];
    return { draw: (ctx, op) => scantraceTextDraw(st, seen, f, ctx, op) };
  };
  return { frame, stats: () => ({ ...st.stats }) };
}

// One step of the bitmaps' hash of numbers.
function scantraceMix(h, v) {
  h = Math.imul(h ^ ((v * 4096) | 0), 0x85ebca6b);
  return h ^ (h >>> 13);
}

// Arrays of equal numbers (a plain loop: every() with a closure cost 0.1 ms of a 3.5 ms frame,
// the two scripts alternated frame by frame along a drag).
function scantraceSameNumbers(a, b) {
  if (a.length !== b.length) return false;
  for (let i = 0; i < a.length; ++i) if (a[i] !== b[i]) return false;
  return true;
}

// The registry's glyph with these strokes: ids are never reused, so a key made before the
// registry was emptied cannot match a bitmap made after.
function scantraceTextGlyph(st, strokes) {
  let h = strokes.length;
  for (const s of strokes) {
    h = scantraceMix(h, s.length);
    for (let i = 0; i < s.length; ++i) h = scantraceMix(h, s[i]);
  }
  const bucket = st.glyphs.get(h) || [];
  for (const g of bucket) if (g.strokes.length === strokes.length && g.strokes.every((s, i) => scantraceSameNumbers(s, strokes[i]))) return g;
  if (st.stats.glyphs >= 4 * st.limit) {
    st.glyphs.clear();
    st.stats.glyphs = 0;
  }
  const box = [Infinity, Infinity, -Infinity, -Infinity];
  for (const s of strokes)
    for (let i = 0; i < s.length; i += 2) {
      box[0] = Math.min(box[0], s[i]);
      box[1] = Math.min(box[1], s[i + 1]);
      box[2] = Math.max(box[2], s[i]);
      box[3] = Math.max(box[3], s[i + 1]);
    }
  const g = { strokes, id: st.nextGlyph++, box };
  bucket.push(g);
  st.glyphs.set(h, bucket);
  ++st.stats.glyphs;
  return g;
}

// Bitmap `b` dropped, its canvas kept for reuse (at most 64 kept).
function scantraceTextDrop(st, b) {
  st.recent.delete(b);
  const bucket = st.ops.get(b.hash);
  bucket.splice(bucket.indexOf(b), 1);
  if (!bucket.length) st.ops.delete(b.hash);
  if (!b.image) return;
  const { canvas } = b.image, size = canvas.width * 65536 + canvas.height;
  st.stats.area -= canvas.width * canvas.height;
  if (st.stats.spare >= 64) return;
  if (!st.spare.has(size)) st.spare.set(size, []);
  st.spare.get(size).push(canvas);
  ++st.stats.spare;
}

// A cleared canvas of at least w x h pixels: sizes rounded up to 32 x 8, and a dropped bitmap's
// canvas of the size taken again. A new canvas, or a canvas resized, for each bitmap made cost
// more than its strokes (Chromium allocates its pixels anew: 1.7-3.5 ms for a drag move's 15
// changed labels, against 0.2-0.5 reusing canvases).
function scantraceTextBlank(st, w, h) {
  const width = Math.ceil(w / 32) * 32, height = Math.ceil(h / 8) * 8;
  const pool = st.spare.get(width * 65536 + height);
  if (pool && pool.length) {
    --st.stats.spare;
    const canvas = pool.pop();
    const g = canvas.getContext('2d');
    g.setTransform(1, 0, 0, 1, 0, 0); // a scaled bitmap's canvas keeps its scale
    g.clearRect(0, 0, width, height);
    return canvas;
  }
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  return canvas;
}

// The op's glyphs stroked onto a canvas of their box, at phase (fx, fy) and scale (sx, sy);
// null for no strokes.
function scantraceTextBitmap(st, frame, op, fx, fy, used, sx, sy) {
  const [, , , , colour, t, placed] = op;
  const box = [Infinity, Infinity, -Infinity, -Infinity];
  for (let k = 0, j = 0; k < placed.length; k += 3, ++j) {
    const dx = placed[k + 1] - placed[1], dy = placed[k + 2] - placed[2], b = used[j].box;
    box[0] = Math.min(box[0], dx + b[0]);
    box[1] = Math.min(box[1], dy + b[1]);
    box[2] = Math.max(box[2], dx + b[2]);
    box[3] = Math.max(box[3], dy + b[3]);
  }
  if (!(box[0] <= box[2])) return null;
  const pad = Math.ceil(t * Math.max(sx, sy) / 2) + 2;
  const left = Math.floor(box[0] * sx) - pad, top = Math.floor(box[1] * sy) - pad;
  const width = Math.ceil(box[2] * sx) + pad + 1 - left, height = Math.ceil(box[3] * sy) + pad + 1 - top;
  const canvas = scantraceTextBlank(st, width, height), g = canvas.getContext('2d');
  g.setTransform(sx, 0, 0, sy, 0, 0);
  g.strokeStyle = colour;
  g.lineWidth = t;
  g.lineCap = 'round';
  g.lineJoin = 'round';
  scantraceStrokeGlyphs(g, frame.glyphs, placed, (fx - left) / sx - placed[1], (fy - top) / sy - placed[2]);
  st.stats.area += canvas.width * canvas.height;
  return { canvas, left, top, width, height };
}

// A "G" op drawn from its bitmap, made if missing; `seen`: the frame's glyph ids -> the
// registry's glyphs.
function scantraceTextDraw(st, seen, f, ctx, op) {
  const colour = op[4], t = op[5], placed = op[6];
  if (!placed.length) return;
  // On a scaled context the bitmap is made at the scale, put at whole canvas pixels.
  const m = ctx.getTransform(), scaled = m.a !== 1 || m.d !== 1;
  const x = scaled ? m.a * (placed[1] + 0.5) + m.e : placed[1] + 0.5;
  const y = scaled ? m.d * (placed[2] + 0.5) + m.f : placed[2] + 0.5;
  const ix = Math.floor(x), iy = Math.floor(y);
  const key = [t, x - ix, y - iy, m.a, m.d], used = [];
  let h = scantraceMix(scantraceMix(scantraceMix(scantraceMix(placed.length, t), x - ix), y - iy), m.a);
  for (let k = 0; k < placed.length; k += 3) {
    const g = seen[placed[k]] || (seen[placed[k]] = scantraceTextGlyph(st, f.glyphs[placed[k]]));
    used.push(g);
    key.push(g.id, placed[k + 1] - placed[1], placed[k + 2] - placed[2]);
    h = scantraceMix(scantraceMix(scantraceMix(h, g.id), placed[k + 1] - placed[1]), placed[k + 2] - placed[2]);
  }
  const bucket = st.ops.get(h) || [];
  let b = bucket.find((e) => e.colour === colour && scantraceSameNumbers(e.key, key));
  if (b) {
    ++st.stats.hits;
    st.recent.delete(b);
  } else {
    ++st.stats.misses;
    b = { hash: h, colour, key, image: scantraceTextBitmap(st, f, op, x - ix, y - iy, used, m.a, m.d) };
    bucket.push(b);
    st.ops.set(h, bucket);
  }
  st.recent.add(b);
  const image = b.image;
  if (image && scaled) ctx.setTransform(1, 0, 0, 1, 0, 0);
  if (image) ctx.drawImage(image.canvas, 0, 0, image.width, image.height, ix + image.left, iy + image.top, image.width, image.height);
  if (image && scaled) ctx.setTransform(m);
  for (const old of st.recent) {
    if (st.recent.size <= st.limit && st.stats.area <= st.maxArea) break;
    if (old !== b) scantraceTextDrop(st, old);
  }
  st.stats.bitmaps = st.recent.size;
}
