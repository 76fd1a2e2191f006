// The explorer's state and its address (#triangle=20,20;250,80;300,400&shading=gouraud&step=12):
// a teacher links a step by copying the address bar. `step` is the index of the step in the
// plan (0 for the first); the address holds the number the page shows, `step 12` for step=12,
// as the trace page's #step=12 does. Also the page's state while it runs (`ex`) and the model:
// the module run on the state (the fill, the trace, its plan of steps, the step's frame). The
// explorer's modules share one scope in the page (make_page.mjs): names are unique across them.
import { putFill, redraw, show, showError } from './view.js';

// The state's defaults; the fill options' (namedOptions) are the module's option tables'.
export const defaults = {
  mode: 'triangle',
  triangle: [[20, 20], [250, 80], [300, 400]],
  // Polygon mode: one closed contour (a star: it crosses itself, so the winding rule shows).
  polygon: [[256, 40], [380, 440], [60, 190], [450, 190], [130, 440]],
  colors: [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
  size: [512, 512],
  subpixel_bits: 8,
  // Scanlines a step: 0 lets the composer choose (at most 40 scanline steps a triangle).
  rows_per_step: 0,
  step: 0,
};

// The state's named fill options, each the key of its table (src/option_table.hpp) as the
// module's optionTable() gives it: their names and defaults are the tables', spelled only there.
export const namedOptions = { shading: 'shading', fill_rule: 'fill_rule', method: 'method', winding: 'winding_rule' };

const hex = (c) => '#' + c.map((v) => Math.round(v * 255).toString(16).padStart(2, '0')).join('');
export const toHex = hex;
export const fromHex = (h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16) / 255);

export function toHash(s) {
  const p = new URLSearchParams();
  if (s.mode === 'triangle') p.set('triangle', s.triangle.map((v) => v.join(',')).join(';'));
  else if (s.mode === 'polygon') {
    p.set('polygon', s.polygon.map((v) => v.join(',')).join(';'));
    p.set('winding', s.winding);
  } else p.set('scene', s.sceneName || 'demo');
  p.set('colors', s.colors.map((c) => hex(c).slice(1)).join(';'));
  p.set('size', s.size.join('x'));
  for (const k of ['shading', 'fill_rule', 'subpixel_bits', 'method']) p.set(k, String(s[k]));
  if (s.rows_per_step) p.set('rows', String(s.rows_per_step));
  p.set('step', String(s.step + 1));
  return '#' + p.toString().replace(/%2C/g, ',').replace(/%3B/g, ';');
}

// The state in `hash`, each value checked; what is missing or malformed keeps its default.
// `table`: the module's optionTable(), the named options' names and defaults.
export function fromHash(hash, table = ex.st.optionTable()) {
  const s = structuredClone(defaults);
  const p = new URLSearchParams(hash.replace(/^#/, ''));
  for (const [key, tableKey] of Object.entries(namedOptions)) {
    const { names, default: fallback } = table[tableKey];
    s[key] = names.includes(p.get(key)) ? p.get(key) : fallback;
  }
  const num = (t) => (/^-?\d+(\.\d+)?(e-?\d+)?$/i.test(t) ? Number(t) : NaN);
  if (p.has('triangle')) {
    const v = p.get('triangle').split(';').map((xy) => xy.split(',').map(num));
    if (v.length === 3 && v.every((xy) => xy.length === 2 && xy.every(Number.isFinite))) s.triangle = v;
  }
  if (p.has('polygon')) {
    const v = p.get('polygon').split(';').map((xy) => xy.split(',').map(num));
    if (v.length >= 3 && v.length <= 64 && v.every((xy) => xy.length === 2 && xy.every(Number.isFinite))) {
      s.polygon = v;
      s.mode = 'polygon';
    }
  }
  if (p.has('scene')) {
    s.mode = 'scene';
    s.sceneName = p.get('scene');
  }
  if (p.has('colors')) {
    const c = p.get('colors').split(';');
    if (c.length === 3 && c.every((h) => /^[0-9a-f]{6}$/i.test(h))) s.colors = c.map((h) => fromHex('#' + h));
  }
  if (p.has('size')) {
    const m = /^(\d+)x(\d+)$/.exec(p.get('size'));
    if (m && +m[1] > 0 && +m[2] > 0 && +m[1] <= 4096 && +m[2] <= 4096) s.size = [+m[1], +m[2]];
  }
  const bits = num(p.get('subpixel_bits') || '');
  if (Number.isInteger(bits) && bits >= 0 && bits <= 12) s.subpixel_bits = bits;
  const rows = num(p.get('rows') || '');
  if ([1, 10].includes(rows)) s.rows_per_step = rows;
  const step = num(p.get('step') || '');
  if (Number.isInteger(step) && step >= 1) s.step = step - 1;
  return s;
}

// The page's state while it runs (the modules share it; start() in explorer.js fills in the
// module and the canvases).
export const ex = {
  st: null, // the WebAssembly module's API (scantrace.mjs)
  drawFrame: null, // the canvas backend's drawScantraceFrame
  s: null, // the state the address holds (above)
  scene: null, // scene mode: {name, data}
  sceneObj: null, // the scene the grid shows (triangle mode: the triangle as a one-face scene)
  traceText: '',
  plan: [],
  fill: null,
  diffPicture: null,
  diffReport: null,
  traceImage: null, // the ImageData the traced fill's image is copied into, move after move
  shown: null, // the module's keptStep of the current step: the tables' events
  shownFrame: null, // the current step's frame as composed
  // The point (0, 0) of the image's plane at screen (x, y), `zoom` screen pixels a pixel. Pixel
  // (x, y) is centred on the integer point (x, y), where the fill samples it (docs/design.md §1):
  // its square is [x - 1/2, x + 1/2] x [y - 1/2, y + 1/2], and a vertex at integer coordinates
  // sits on a pixel centre.
  view: { zoom: 1, x: 0, y: 0 },
  drag: null,
  marked: null,
  awaited: null, // a link's scene not yet opened: {name, step}
  dragTimes: [],
  dragStages: [],
  lastStages: null,
  grid: null,
  gctx: null,
  frame: null,
  fctx: null,
  // The fill is shown in its own pixels on a canvas of its own under the grid's, scaled and
  // moved by the browser (a CSS transform: the view's zoom and offset), the grid's canvas holding
  // only what is drawn over it. Drawn into the grid's canvas, 512 x 512 pixels scaled to 720 x 720
  // on every mouse move, the fill was a tenth of a drag move's time rasterised
  // (docs/performance.md).
  fillCanvas: null,
  // The canvases' boxes' widths, kept from the last layout (ResizeObservers, controller.js):
  // reading clientWidth in a mouse move made the browser lay the page out there and then.
  frameBoxWidth: 0,
  gridBoxWidth: 0,
  placed: '', // the fill canvas's transform as last set
};

// --- the model: the module run on the state ----------------------------------------------------
export function fillOptions() {
  const o = { shading: ex.s.shading, fill_rule: ex.s.fill_rule, subpixel_bits: ex.s.subpixel_bits, method: ex.s.method };
  return ex.s.mode === 'polygon' ? { ...o, winding: ex.s.winding } : o;
}

// The vertices the grid shows and drags: the triangle's, the polygon's, none for a scene.
export const vertices = () => (ex.s.mode === 'triangle' ? ex.s.triangle : ex.s.mode === 'polygon' ? ex.s.polygon : []);

export function triangleScene() {
  return {
    width: ex.s.size[0], height: ex.s.size[1], background: [1, 1, 1],
    vertices: ex.s.triangle, vcolors: ex.s.colors, faces: [[0, 1, 2]], depth: [0, 0, 0],
  };
}

// Re-runs the module on the state: the fill, the trace, its steps and the current step's frame,
// all drawn before this returns (a drag calls it on every mouse move: docs/performance.md).
// `moving`: a drag's mouse move, where the trace is kept in the module without its JSON Lines
// (the tables read the step's events from the module); the release writes them.
export function recompute(moving = false) {
  const t0 = performance.now();
  // Milliseconds from the start to the end of each stage (the bench's breakdown of a move).
  const stages = { trace: 0, fill: 0, frame: 0, grid: 0, step: 0, drawn: 0 };
  ex.lastStages = stages;
  showError(null);
  try {
    ex.sceneObj = ex.s.mode === 'triangle' ? triangleScene() : null;
    // A scene's fill is its render; a triangle's or polygon's is the image its traced fill drew
    // (the same pixels as the render of the one-face scene, the node test holds it to that; one
    // fill a mouse move instead of two).
    if (ex.s.mode === 'scene') ex.fill = ex.st.render(ex.scene, fillOptions());
    const traced = ex.s.mode === 'triangle'
      ? { triangle: ex.s.triangle, colors: ex.s.colors, width: ex.s.size[0], height: ex.s.size[1] }
      : ex.s.mode === 'polygon' ? { polygon: [ex.s.polygon], width: ex.s.size[0], height: ex.s.size[1] } : { scene: ex.scene };
    // Kept in the module for the frames of its steps (composeStep); a triangle's or polygon's
    // image copied into the ImageData kept for it (traceImage).
    if (ex.s.mode !== 'scene' && !(ex.traceImage && ex.traceImage.width === ex.s.size[0] && ex.traceImage.height === ex.s.size[1]))
      ex.traceImage = new ImageData(ex.s.size[0], ex.s.size[1]);
    const text = ex.st.traceText(traced, { ...fillOptions(), level: ex.s.mode === 'scene' ? 'triangle' : 'scanline', keep: true, text: !moving }, ex.s.mode === 'scene' ? null : ex.traceImage);
    ex.traceText = moving ? null : text;
    const traceMs = performance.now() - t0;
    stages.trace = traceMs;
    if (ex.s.mode !== 'scene') ex.fill = { ...ex.st.lastTraceImage, ms: traceMs };
    putFill();
    stages.fill = performance.now() - t0;
    composeStep();
    stages.frame = performance.now() - t0;
    show('fill-ms', ex.s.mode === 'scene' ? `render ${ex.fill.ms.toFixed(2)} ms` : `fill and trace ${ex.fill.ms.toFixed(1)} ms`);
  } catch (e) {
    showError(e);
  }
  redraw(stages, t0);
  stages.drawn = performance.now() - t0;
  document.body.dataset.recomputeMs = (performance.now() - t0).toFixed(1);
}

// The frame's size: the canvas's box on the screen in device pixels, 16:9, at most the 1280 x 720
// of the videos and at least the composer's 320 x 180. A 1280-wide frame shown in a 690-pixel
// column was scaled down by the browser: composing and drawing 3.4 times the pixels shown was
// most of a drag move's drawing (docs/performance.md); composed at the size shown, the frame's
// text and grid are drawn sharp, not resampled.
// In presentation the frame fills the screen: composed up to 1920 wide, its text as large.
export function frameSize() {
  const most = document.body.classList.contains('presenting') ? 1920 : 1280;
  const w = Math.round(Math.max(320, Math.min(most, ex.frameBoxWidth * (window.devicePixelRatio || 1))));
  return { width: w, height: Math.max(180, Math.round((w * 9) / 16)) };
}

// The plan of steps and the current step's frame from one call (one plan), the frame's pixel
// blocks as bytes: nothing waits for an image to load. The frame handed over as numbers, not
// JSON (writing its numbers as text and parsing them back was a fifth of a drag's move).
export function composeStep() {
  const source = ex.s.mode === 'scene' ? ex.scene.name : `the explorer\u2019s ${ex.s.mode}`;
  const options = { count: 1, source, blocks: 'rgba', encoding: 'binary', rows_per_step: ex.s.rows_per_step, ...frameSize() };
  let r = ex.st.frames(null, { ...options, first: ex.s.step });
  ex.plan = r.steps;
  if (ex.s.step >= ex.plan.length && ex.plan.length) {
    ex.s.step = ex.plan.length - 1;
    r = ex.st.frames(null, { ...options, first: ex.s.step });
  }
  ex.shownFrame = r.frames[0] || null;
  // The tables' events: the step's face's edge table and, for a scanline step, its row.
  const step = ex.plan[ex.s.step];
  ex.shown = ex.st.keptStep(step ? Math.max(0, step.triangle) : 0, step && step.kind === 'scanlines' ? step.last_row : -1);
}

// `stages` (a drag's move): the end of each drawing, ms from t0, kept for the bench.

export function currentStep() {
  return ex.plan[ex.s.step] || null;
}

export function setStep(k) {
  ex.s.step = Math.max(0, Math.min(ex.plan.length - 1, k));
  try {
    composeStep();
  } catch (e) {
    showError(e);
  }
  redraw();
}

