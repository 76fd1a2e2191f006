// The explorer's view (docs/web.md): what the page draws and writes from the state (state.js's
// `ex`): the fill on its canvas, the grid over it (pixel squares, centres, the scanline, the
// vertices, the marked pixel, a diff's picture), the step's frame, the tables, the step list and
// the sentences said, the answers. Nothing here reads input. The explorer's modules share one
// scope in the page (make_page.mjs): names are unique across them.
import { currentStep, ex, toHash, toHex, vertices } from './state.js';
import { diffSummary, whyProse } from './answers.js';
import { showStepList, stepSentence, stepTitle } from './controls.js';

export const $ = (id) => document.getElementById(id);

// A text shown, set only when it changed: every text set makes the browser lay the page out
// again before the next mouse move is dispatched (its hit test), and a drag's move sets seven.
export function show(id, text) {
  const el = $(id);
  if (el.textContent !== text) el.textContent = text;
}

export function showError(e) {
  show('error', e ? `error: ${e.message || e}` : '');
  if ($('error').hidden !== !e) $('error').hidden = !e;
}

// The traced fill put on its canvas. (Putting only the rows a drag's move can change, those of
// the vertices' boxes before and after it, measured no faster: docs/performance.md.)
export function putFill() {
  if (ex.fillCanvas.width !== ex.fill.width || ex.fillCanvas.height !== ex.fill.height) {
    ex.fillCanvas.width = ex.fill.width;
    ex.fillCanvas.height = ex.fill.height;
  }
  const image = ex.traceImage && ex.fill.rgba === ex.traceImage.data ? ex.traceImage : new ImageData(ex.fill.rgba, ex.fill.width, ex.fill.height);
  ex.fillCanvas.getContext('2d').putImageData(image, 0, 0);
}

// `stages` (a drag's move): the end of each drawing, ms from t0, kept for the bench.
export function redraw(stages = null, t0 = 0) {
  drawGrid();
  if (stages) stages.grid = performance.now() - t0;
  drawStep();
  if (stages) stages.step = performance.now() - t0;
  showTables();
  // The address follows the state, but not on every mouse move of a drag (a replaceState cost
  // 5 ms of the move's time): the release writes it.
  // Nor while a link's scene is awaited: the address stays the link's.
  if (!(ex.drag && ex.drag.vertex !== undefined) && !ex.awaited) history.replaceState(null, '', toHash(ex.s));
}

export function fitView() {
  const w = ex.s.mode !== 'scene' ? ex.s.size[0] : ex.fill ? ex.fill.width : 512;
  const h = ex.s.mode !== 'scene' ? ex.s.size[1] : ex.fill ? ex.fill.height : 512;
  ex.view.zoom = Math.max(0.25, Math.min(ex.grid.width / w, ex.grid.height / h));
  // The image covers [-1/2, w - 1/2] x [-1/2, h - 1/2]: centred in the grid.
  ex.view.x = (ex.grid.width - w * ex.view.zoom) / 2 + ex.view.zoom / 2;
  ex.view.y = (ex.grid.height - h * ex.view.zoom) / 2 + ex.view.zoom / 2;
}

export const toScreen = ([x, y]) => [ex.view.x + x * ex.view.zoom, ex.view.y + y * ex.view.zoom];
export const toCanvas = (px, py) => [(px - ex.view.x) / ex.view.zoom, (py - ex.view.y) / ex.view.zoom];
// The pixel whose square holds a screen point: the nearest centre.
export const pixelAt = (px, py) => toCanvas(px, py).map(Math.round);

// Grid canvas pixels a CSS pixel (the grid's 720 pixels over its box: 2 on a phone).
export const canvasPerCss = () => ex.grid.width / (ex.gridBoxWidth || ex.grid.width);
// The handles: drawn at least 7 canvas (and 6 CSS) pixels in radius (taken within 12 CSS
// pixels: controller.js's vertexAt).
export const handleRadius = () => Math.max(7, 6 * canvasPerCss());

// The fill canvas placed where the view puts the image: grid canvas pixels to CSS pixels (the
// grid's box over its 720 pixels), then the view's offset and zoom, then half a pixel up and
// left (the canvas's pixel x spans [x, x + 1]; the image's pixel x, [x - 1/2, x + 1/2]). Set
// only when it changes (a pan, a zoom, a resize): a drag's move leaves it.
export function placeFill() {
  const k = ex.gridBoxWidth / ex.grid.width;
  const transform = `scale(${k}) translate(${ex.view.x}px, ${ex.view.y}px) scale(${ex.view.zoom}) translate(-0.5px, -0.5px)`;
  if (transform !== ex.placed) ex.fillCanvas.style.transform = ex.placed = transform;
  ex.fillCanvas.hidden = !ex.fill;
}

// The pixel grid at zoom: the squares' sides on half-integer lines and, once the squares are
// large enough to see them, a dot on each pixel centre (where coverage is decided).
export function drawPixelGrid(z) {
  const [cx0, cy0] = pixelAt(0, 0).map((v) => Math.max(0, v));
  const [cx1, cy1] = pixelAt(ex.grid.width, ex.grid.height);
  const x1 = Math.min(cx1, ex.fillCanvas.width - 1), y1 = Math.min(cy1, ex.fillCanvas.height - 1);
  ex.gctx.strokeStyle = 'rgba(0,0,0,0.15)';
  ex.gctx.lineWidth = 1;
  ex.gctx.beginPath();
  for (let x = cx0; x <= x1 + 1; ++x) {
    ex.gctx.moveTo(...toScreen([x - 0.5, cy0 - 0.5]));
    ex.gctx.lineTo(...toScreen([x - 0.5, y1 + 0.5]));
  }
  for (let y = cy0; y <= y1 + 1; ++y) {
    ex.gctx.moveTo(...toScreen([cx0 - 0.5, y - 0.5]));
    ex.gctx.lineTo(...toScreen([x1 + 0.5, y - 0.5]));
  }
  ex.gctx.stroke();
  if (z < 12) return;
  ex.gctx.fillStyle = 'rgba(0,0,0,0.45)';
  const r = Math.max(1, z / 16);
  for (let y = cy0; y <= y1; ++y) {
    for (let x = cx0; x <= x1; ++x) {
      const [px, py] = toScreen([x, y]);
      ex.gctx.fillRect(px - r, py - r, 2 * r, 2 * r);
    }
  }
}

export function drawGrid() {
  ex.gctx.setTransform(1, 0, 0, 1, 0, 0);
  ex.gctx.clearRect(0, 0, ex.grid.width, ex.grid.height);
  placeFill();
  const z = ex.view.zoom;
  if (ex.diffPicture) {
    const c = document.createElement('canvas');
    c.width = ex.diffPicture.width;
    c.height = ex.diffPicture.height;
    c.getContext('2d').putImageData(new ImageData(ex.diffPicture.rgba, ex.diffPicture.width, ex.diffPicture.height), 0, 0);
    ex.gctx.imageSmoothingEnabled = false;
    ex.gctx.drawImage(c, ex.view.x - z / 2, ex.view.y - z / 2, c.width * z, c.height * z);
  }
  if (z >= 6) drawPixelGrid(z);
  const step = currentStep();
  if (step && step.kind === 'scanlines') {
    // The current scanline through the pixel centres of its row: y = the row, where the
    // vertices at integer coordinates lie.
    ex.gctx.strokeStyle = '#c00';
    ex.gctx.lineWidth = 2;
    ex.gctx.beginPath();
    const [, sy] = toScreen([0, step.last_row]);
    ex.gctx.moveTo(ex.view.x - z / 2, sy);
    ex.gctx.lineTo(ex.view.x + (ex.fillCanvas.width - 0.5) * z, sy);
    ex.gctx.stroke();
  }
  if (ex.s.mode !== 'scene') {
    ex.gctx.strokeStyle = '#000';
    ex.gctx.lineWidth = 1.5;
    ex.gctx.beginPath();
    vertices().forEach((v, i) => {
      const [px, py] = toScreen(v);
      if (i === 0) ex.gctx.moveTo(px, py);
      else ex.gctx.lineTo(px, py);
    });
    ex.gctx.closePath();
    ex.gctx.stroke();
    vertices().forEach((v, i) => {
      const [px, py] = toScreen(v);
      // A polygon's vertices take the command's default colours: red, green, blue, repeated.
      ex.gctx.fillStyle = ex.s.mode === 'triangle' ? toHex(ex.s.colors[i]) : ['#ff0000', '#00ff00', '#0000ff'][i % 3];
      ex.gctx.strokeStyle = '#000';
      ex.gctx.beginPath();
      ex.gctx.arc(px, py, handleRadius(), 0, 2 * Math.PI);
      ex.gctx.fill();
      ex.gctx.stroke();
    });
  }
  if (ex.marked) {
    ex.gctx.strokeStyle = '#f0f';
    ex.gctx.lineWidth = 2;
    const [px, py] = toScreen([ex.marked[0] - 0.5, ex.marked[1] - 0.5]);
    ex.gctx.strokeRect(px, py, Math.max(3, z), Math.max(3, z));
  }
}

export function drawStep() {
  const n = ex.plan.length;
  show('step-no', n ? `step ${ex.s.step + 1} / ${n}` : 'no steps');
  const slider = $('slider');
  if (slider.max !== String(Math.max(0, n - 1))) slider.max = String(Math.max(0, n - 1));
  if (slider.value !== String(ex.s.step)) slider.value = String(ex.s.step);
  if (!n || !ex.shownFrame) return;
  if (ex.frame.width !== ex.shownFrame.w || ex.frame.height !== ex.shownFrame.h) {
    ex.frame.width = ex.shownFrame.w;
    ex.frame.height = ex.shownFrame.h;
  }
  ex.drawFrame(ex.fctx, ex.shownFrame);
  if (ex.frame.dataset.step !== String(ex.s.step)) ex.frame.dataset.step = String(ex.s.step);
}

export function showTables() {
  const step = currentStep();
  show('step-kind', step ? stepTitle(ex.plan, ex.s.step) : '');
  const row = step && step.kind === 'scanlines' && ex.shown ? ex.shown.scanline : null;
  // The step list, the sentence said and the labels follow the plan, but not on a drag's
  // mouse move (a screen reader would be told every move): the release writes them.
  if (!(ex.drag && ex.drag.vertex !== undefined)) {
    showStepList(ex.plan, ex.s.step);
    const sentence = step ? stepSentence(ex.plan, ex.s.step, row) : 'no steps';
    show('announce', sentence);
    const label = `the step's frame. ${sentence}`;
    if (ex.frame.getAttribute('aria-label') !== label) ex.frame.setAttribute('aria-label', label);
    if (ex.grid.getAttribute('aria-label') !== gridLabel()) ex.grid.setAttribute('aria-label', gridLabel());
    const title = `scantrace explorer: ${shownName()}${step ? `, step ${ex.s.step + 1} of ${ex.plan.length}` : ''}`;
    if (document.title !== title) document.title = title;
  }
  const table = ex.shown && ex.shown.edge_table;
  show('edge-table', table
    ? table.edges.map((e) => `edge ${e.edge}: (${e.from}) -> (${e.to})  rows ${e.first_row}..${e.last_row}  x@ymin ${e.x_at_y_min}  dx/dy ${e.dx_dy}`).join('\n')
    : '(none: the trace is at triangle level, or no edge)');
  show('active', row
    ? [`y = ${row.y}  entered [${row.entered}]  retired [${row.retired}]`,
      ...row.active_edges.map((a) => `edge ${a.edge}  x = ${a.x}`),
      ...(row.active_points || []).map((p) => `point x = ${p.x}  colour (${p.color.map((c) => c.toFixed(3)).join(', ')})`),
      ...(row.span ? [`span [${row.span.x_begin}, ${row.span.x_end})`] : []),
      ...((row.spans || []).map((sp) => `span [${sp.x_begin}, ${sp.x_end})`))].join('\n')
    : '(choose a scanline step: \u2192 \u2190)');
  show('events', !ex.shown ? ''
    : ex.traceText === null ? `${ex.shown.events} events (their JSON Lines written when the vertex is let go)`
      : `${ex.shown.events} events, ${ex.traceText.length} bytes of JSON Lines`);
}

// What the grid shows, in words: the page's title and the grid's label.
export const shownName = () => (ex.s.mode === 'scene' ? `scene ${ex.s.sceneName}` : `${ex.s.mode} ${vertices().map((v) => `(${v.join(',')})`).join(' ')}`);
export function gridLabel() {
  const what = `the ${shownName()}`;
  const size = ex.s.mode === 'scene' && ex.fill ? [ex.fill.width, ex.fill.height] : ex.s.size;
  return `the pixel grid: ${what}, ${size.join(' by ')} pixels${ex.marked ? `, pixel (${ex.marked.join(', ')}) marked` : ''}`;
}

// story: the module's why document, text its lastWhyText; none: `note` alone.
export function showWhy(story, text = '', note = '') {
  const prose = story ? whyProse(story, text) : { answer: note, text: '' };
  $('why-answer').textContent = prose.answer;
  $('why').textContent = prose.text;
  $('why').hidden = !story;
  $('why-json').textContent = story ? JSON.stringify(story, null, 1) : '';
  $('why-json-box').hidden = !story;
}

// A diff's summary (verdict, the colours of the picture with their counts, the patterns), the
// report's JSON written into its toggle only when opened: 80,000 lines for a wrong scene.
export function showDiff(report) {
  ex.diffReport = report;
  const sum = diffSummary(report);
  $('diff-box').hidden = false;
  $('diff-verdict').textContent = sum.verdict;
  $('diff-legend').replaceChildren(...sum.legend.map(([c, n, rgb, pc]) => {
    const li = document.createElement('li');
    const sw = document.createElement('span');
    sw.className = 'swatch';
    sw.style.background = `rgb(${rgb.join(',')})`;
    li.dataset.category = c;
    li.dataset.rgb = rgb.join(',');
    li.append(sw, `${c.replace(/_/g, ' ')}: ${n} (${pc.toFixed(1)} %)`);
    return li;
  }));
  $('diff-lines').replaceChildren(...sum.lines.map((line) => {
    const p = document.createElement('div');
    p.textContent = line;
    return p;
  }));
  $('diff-json').textContent = '';
  if ($('diff-json-box').open) $('diff-json').textContent = JSON.stringify(report, null, 1);
}

export function bindDiffToggle() {
  $('diff-json-box').addEventListener('toggle', () => {
    if ($('diff-json-box').open && ex.diffReport && !$('diff-json').textContent) $('diff-json').textContent = JSON.stringify(ex.diffReport, null, 1);
  });
}

