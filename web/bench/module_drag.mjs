// The WebAssembly module's share of an explorer drag's mouse move (docs/performance.md, "In the
// browser"), in Node: the three calls recompute() and composeStep() make (web/explorer/explorer.js)
// for the course triangle (gouraud, 512 x 512, step 13 shown, the frame 688 x 387) while vertex
// 2 moves along 27 (1 - cos 0.1 i) px as web/bench/explorer_drag.mjs moves it: traceText (keep,
// no text, into one ImageData-sized array), frames (one step, rgba blocks, binary encoding) and
// keptStep. Medians of each call and of the move.
//
//   node web/bench/module_drag.mjs WEB_DIR [MOVES] [OTHER_WEB_DIR]
// With OTHER_WEB_DIR (another build's build/web, e.g. main's), the two modules are loaded in the
// same process and alternate move by move (which one goes first alternating too), and each move's
// image, frame and step of the two are checked equal: the cuts must not change any output.
import path from 'node:path';
import { isDeepStrictEqual } from 'node:util';
import { pathToFileURL } from 'node:url';

const [webDir, movesArg, otherDir] = process.argv.slice(2);
if (!webDir) {
  console.error('usage: node web/bench/module_drag.mjs WEB_DIR [MOVES] [OTHER_WEB_DIR]');
  process.exit(2);
}
const moves = Number(movesArg || 400), warmup = 30;
const median = (v) => [...v].sort((a, b) => a - b)[v.length >> 1];
const quartiles = (v) => { const s = [...v].sort((a, b) => a - b); return [s[s.length >> 2], s[(3 * s.length) >> 2]]; };

const dirs = otherDir ? [webDir, otherDir] : [webDir];
const modules = [];
for (const dir of dirs) {
  const { load } = await import(pathToFileURL(path.join(path.resolve(dir), 'scantrace.mjs')));
  modules.push(await load());
}

const base = [[20, 20], [250, 80], [300, 400]];
const colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
const fill = { shading: 'gouraud', fill_rule: 'top-left', subpixel_bits: 8, method: 'exact' };
const size = { width: 688, height: 387 };
const step = 12;

// One mouse move of the explorer's drag on module `st`: its calls' times and what they gave.
function move(st, triangle, image) {
  const t0 = performance.now();
  st.traceText({ triangle, colors, width: 512, height: 512 }, { ...fill, level: 'scanline', keep: true, text: false }, image);
  const t1 = performance.now();
  const r = st.frames(null, { count: 1, source: 'the explorer\u2019s triangle', blocks: 'rgba', encoding: 'binary', ...size, first: step });
  const t2 = performance.now();
  const s = r.steps[step];
  const shown = st.keptStep(s ? Math.max(0, s.triangle) : 0, s && s.kind === 'scanlines' ? s.last_row : -1);
  const t3 = performance.now();
  return { ms: [t1 - t0, t2 - t1, t3 - t2, t3 - t0], steps: r.steps, frame: r.frames[0], shown };
}

// A frame as plain data, its blocks expanded, for comparing two modules' frames.
const plain = (frame) => frame && {
  ...frame,
  ops: frame.ops.map((op) => op.map((v) => (v instanceof Float64Array ? Array.from(v) : v && v.texels ? Array.from(v.data) : v))),
  glyphs: frame.glyphs.map((g) => g.map((s) => Array.from(s))),
};

const times = modules.map(() => []);
const images = modules.map(() => new Uint8ClampedArray(512 * 512 * 4));
let checked = 0;
for (let i = 1; i <= moves + warmup; ++i) {
  const k = 27 * (1 - Math.cos(i * 0.1));
  // The explorer snaps a dragged vertex to the subpixel grid (8 bits).
  const triangle = [base[0], base[1], [Math.round((300 - k) * 256) / 256, Math.round((400 - 0.6 * k) * 256) / 256]];
  const order = i % 2 ? [...modules.keys()].reverse() : [...modules.keys()];
  const got = [];
  for (const m of order) {
    got[m] = move(modules[m], triangle, images[m]);
    if (i > warmup) times[m].push(got[m].ms);
  }
  // Every 10th move of two modules compared whole (the comparison costs more than the move).
  if (modules.length === 2 && i % 10 === 0) {
    const same = isDeepStrictEqual(Buffer.from(images[0].buffer), Buffer.from(images[1].buffer)) &&
      isDeepStrictEqual(got[0].steps, got[1].steps) && isDeepStrictEqual(got[0].shown, got[1].shown) &&
      isDeepStrictEqual(plain(got[0].frame), plain(got[1].frame));
    if (!same) {
      console.error(`move ${i}: the two modules' image, steps, frame or step events differ`);
      process.exit(1);
    }
    ++checked;
  }
}

const names = ['traceText', 'frames', 'keptStep', 'move'];
dirs.forEach((dir, m) => {
  const col = (c) => times[m].map((t) => t[c]);
  const [q1, q3] = quartiles(col(3));
  console.log(`${dir} (${moves} moves${modules.length > 1 ? ', alternated with the other module' : ''}): ` +
    names.map((n, c) => `${n} ${median(col(c)).toFixed(2)}`).join(', ') +
    ` ms (medians; the move's quartiles ${q1.toFixed(2)}, ${q3.toFixed(2)})`);
});
if (checked) console.log(`${checked} moves compared: the same image, steps, frame and step events`);
