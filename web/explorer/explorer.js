// The explorer page (docs/web.md): drag a triangle's vertices on the pixel grid and watch the
// real fill (the WebAssembly module) redo its edge table, active edge list and spans; step
// through the composer's frames with `scantrace step`'s keys; click a pixel for its `why`; open a
// scene; drop an image rendered for it for a `diff`. The state is kept in the address.
import { fromHash, fromHex, toHash, toHex } from './state.js';
import { diffSummary, whyProse } from './answers.js';
import { bindPlayer, showStepList, stepSentence, stepTitle } from './controls.js';

const $ = (id) => document.getElementById(id);

export async function start(st) {
  const drawFrame = new Function(`${st.canvasScript()}; return drawScantraceFrame;`)();
  let s = fromHash(location.hash);
  let scene = null; // scene mode: {name, data}
  let sceneObj = null; // the scene the grid shows (triangle mode: the triangle as a one-face scene)
  let traceText = '', plan = [], fill = null, diffPicture = null;
  let traceImage = null; // the ImageData the traced fill's image is copied into, move after move
  let shown = null; // the module's keptStep of the current step: the tables' events
  // The point (0, 0) of the image's plane at screen (x, y), `zoom` screen pixels a pixel. Pixel
  // (x, y) is centred on the integer point (x, y), where the fill samples it (docs/design.md §1):
  // its square is [x - 1/2, x + 1/2] x [y - 1/2, y + 1/2], and a vertex at integer coordinates
  // sits on a pixel centre.
  let view = { zoom: 1, x: 0, y: 0 };
  let drag = null, marked = null;
  let awaited = null; // a link's scene not yet opened: {name, step}
  const dragTimes = [], dragStages = [];
  let lastStages = null;

  const grid = $('grid'), gctx = grid.getContext('2d');
  const frame = $('frame'), fctx = frame.getContext('2d');
  // The fill is shown in its own pixels on a canvas of its own under the grid's, scaled and moved
  // by the browser (a CSS transform: the view's zoom and offset), the grid's canvas holding only
  // what is drawn over it. Drawn into the grid's canvas, 512 x 512 pixels scaled to 720 x 720 on
  // every mouse move, the fill was a tenth of a drag move's time rasterised (docs/performance.md).
  const fillCanvas = $('fill');

  // A text shown, set only when it changed: every text set makes the browser lay the page out
  // again before the next mouse move is dispatched (its hit test), and a drag's move sets seven.
  function show(id, text) {
    const el = $(id);
    if (el.textContent !== text) el.textContent = text;
  }

  function showError(e) {
    show('error', e ? `error: ${e.message || e}` : '');
    if ($('error').hidden !== !e) $('error').hidden = !e;
  }

  function fillOptions() {
    const o = { shading: s.shading, fill_rule: s.fill_rule, subpixel_bits: s.subpixel_bits, method: s.method };
    return s.mode === 'polygon' ? { ...o, winding: s.winding } : o;
  }

  // The vertices the grid shows and drags: the triangle's, the polygon's, none for a scene.
  const vertices = () => (s.mode === 'triangle' ? s.triangle : s.mode === 'polygon' ? s.polygon : []);

  function triangleScene() {
    return {
      width: s.size[0], height: s.size[1], background: [1, 1, 1],
      vertices: s.triangle, vcolors: s.colors, faces: [[0, 1, 2]], depth: [0, 0, 0],
    };
  }

  // Re-runs the module on the state: the fill, the trace, its steps and the current step's frame,
  // all drawn before this returns (a drag calls it on every mouse move: docs/performance.md).
  // `moving`: a drag's mouse move, where the trace is kept in the module without its JSON Lines
  // (the tables read the step's events from the module); the release writes them.
  function recompute(moving = false) {
    const t0 = performance.now();
    // Milliseconds from the start to the end of each stage (the bench's breakdown of a move).
    const stages = { trace: 0, fill: 0, frame: 0, grid: 0, step: 0, drawn: 0 };
    lastStages = stages;
    showError(null);
    try {
      sceneObj = s.mode === 'triangle' ? triangleScene() : null;
      // A scene's fill is its render; a triangle's or polygon's is the image its traced fill drew
      // (the same pixels as the render of the one-face scene, the node test holds it to that; one
      // fill a mouse move instead of two).
      if (s.mode === 'scene') fill = st.render(scene, fillOptions());
      const traced = s.mode === 'triangle'
        ? { triangle: s.triangle, colors: s.colors, width: s.size[0], height: s.size[1] }
        : s.mode === 'polygon' ? { polygon: [s.polygon], width: s.size[0], height: s.size[1] } : { scene };
      // Kept in the module for the frames of its steps (composeStep); a triangle's or polygon's
      // image copied into the ImageData kept for it (traceImage).
      if (s.mode !== 'scene' && !(traceImage && traceImage.width === s.size[0] && traceImage.height === s.size[1]))
        traceImage = new ImageData(s.size[0], s.size[1]);
      const text = st.traceText(traced, { ...fillOptions(), level: s.mode === 'scene' ? 'triangle' : 'scanline', keep: true, text: !moving }, s.mode === 'scene' ? null : traceImage);
      traceText = moving ? null : text;
      const traceMs = performance.now() - t0;
      stages.trace = traceMs;
      if (s.mode !== 'scene') fill = { ...st.lastTraceImage, ms: traceMs };
      putFill();
      stages.fill = performance.now() - t0;
      composeStep();
      stages.frame = performance.now() - t0;
      show('fill-ms', s.mode === 'scene' ? `render ${fill.ms.toFixed(2)} ms` : `fill and trace ${fill.ms.toFixed(1)} ms`);
    } catch (e) {
      showError(e);
    }
    redraw(stages, t0);
    stages.drawn = performance.now() - t0;
    document.body.dataset.recomputeMs = (performance.now() - t0).toFixed(1);
  }

  // The traced fill put on its canvas. (Putting only the rows a drag's move can change, those of
  // the vertices' boxes before and after it, measured no faster: docs/performance.md.)
  function putFill() {
    if (fillCanvas.width !== fill.width || fillCanvas.height !== fill.height) {
      fillCanvas.width = fill.width;
      fillCanvas.height = fill.height;
    }
    const image = traceImage && fill.rgba === traceImage.data ? traceImage : new ImageData(fill.rgba, fill.width, fill.height);
    fillCanvas.getContext('2d').putImageData(image, 0, 0);
  }

  // The frame's size: the canvas's box on the screen in device pixels, 16:9, at most the 1280 x 720
  // of the videos and at least the composer's 320 x 180. A 1280-wide frame shown in a 690-pixel
  // column was scaled down by the browser: composing and drawing 3.4 times the pixels shown was
  // most of a drag move's drawing (docs/performance.md); composed at the size shown, the frame's
  // text and grid are drawn sharp, not resampled.
  // The box's width is kept from the last layout (a ResizeObserver, below): reading clientWidth
  // in a mouse move made the browser lay the page out there and then (the tables had changed).
  let frameBoxWidth = frame.clientWidth, gridBoxWidth = grid.clientWidth;
  // In presentation the frame fills the screen: composed up to 1920 wide, its text as large.
  function frameSize() {
    const most = document.body.classList.contains('presenting') ? 1920 : 1280;
    const w = Math.round(Math.max(320, Math.min(most, frameBoxWidth * (window.devicePixelRatio || 1))));
    return { width: w, height: Math.max(180, Math.round((w * 9) / 16)) };
  }

  // The plan of steps and the current step's frame from one call (one plan), the frame's pixel
  // blocks as bytes: nothing waits for an image to load. The frame handed over as numbers, not
  // JSON (writing its numbers as text and parsing them back was a fifth of a drag's move).
  let shownFrame = null;
  function composeStep() {
    const source = s.mode === 'scene' ? scene.name : `the explorer\u2019s ${s.mode}`;
    const options = { count: 1, source, blocks: 'rgba', encoding: 'binary', rows_per_step: s.rows_per_step, ...frameSize() };
    let r = st.frames(null, { ...options, first: s.step });
    plan = r.steps;
    if (s.step >= plan.length && plan.length) {
      s.step = plan.length - 1;
      r = st.frames(null, { ...options, first: s.step });
    }
    shownFrame = r.frames[0] || null;
    // The tables' events: the step's face's edge table and, for a scanline step, its row.
    const step = plan[s.step];
    shown = st.keptStep(step ? Math.max(0, step.triangle) : 0, step && step.kind === 'scanlines' ? step.last_row : -1);
  }

  // `stages` (a drag's move): the end of each drawing, ms from t0, kept for the bench.
  function redraw(stages = null, t0 = 0) {
    drawGrid();
    if (stages) stages.grid = performance.now() - t0;
    drawStep();
    if (stages) stages.step = performance.now() - t0;
    showTables();
    // The address follows the state, but not on every mouse move of a drag (a replaceState cost
    // 5 ms of the move's time): the release writes it.
    // Nor while a link's scene is awaited: the address stays the link's.
    if (!(drag && drag.vertex !== undefined) && !awaited) history.replaceState(null, '', toHash(s));
  }

  function fitView() {
    const w = s.mode !== 'scene' ? s.size[0] : fill ? fill.width : 512;
    const h = s.mode !== 'scene' ? s.size[1] : fill ? fill.height : 512;
    view.zoom = Math.max(0.25, Math.min(grid.width / w, grid.height / h));
    // The image covers [-1/2, w - 1/2] x [-1/2, h - 1/2]: centred in the grid.
    view.x = (grid.width - w * view.zoom) / 2 + view.zoom / 2;
    view.y = (grid.height - h * view.zoom) / 2 + view.zoom / 2;
  }

  const toScreen = ([x, y]) => [view.x + x * view.zoom, view.y + y * view.zoom];
  const toCanvas = (px, py) => [(px - view.x) / view.zoom, (py - view.y) / view.zoom];
  // The pixel whose square holds a screen point: the nearest centre.
  const pixelAt = (px, py) => toCanvas(px, py).map(Math.round);

  function currentStep() {
    return plan[s.step] || null;
  }

  // The fill canvas placed where the view puts the image: grid canvas pixels to CSS pixels (the
  // grid's box over its 720 pixels), then the view's offset and zoom, then half a pixel up and
  // left (the canvas's pixel x spans [x, x + 1]; the image's pixel x, [x - 1/2, x + 1/2]). Set
  // only when it changes (a pan, a zoom, a resize): a drag's move leaves it.
  let placed = '';
  function placeFill() {
    const k = gridBoxWidth / grid.width;
    const transform = `scale(${k}) translate(${view.x}px, ${view.y}px) scale(${view.zoom}) translate(-0.5px, -0.5px)`;
    if (transform !== placed) fillCanvas.style.transform = placed = transform;
    fillCanvas.hidden = !fill;
  }

  // The pixel grid at zoom: the squares' sides on half-integer lines and, once the squares are
  // large enough to see them, a dot on each pixel centre (where coverage is decided).
  function drawPixelGrid(z) {
    const [cx0, cy0] = pixelAt(0, 0).map((v) => Math.max(0, v));
    const [cx1, cy1] = pixelAt(grid.width, grid.height);
    const x1 = Math.min(cx1, fillCanvas.width - 1), y1 = Math.min(cy1, fillCanvas.height - 1);
    gctx.strokeStyle = 'rgba(0,0,0,0.15)';
    gctx.lineWidth = 1;
    gctx.beginPath();
    for (let x = cx0; x <= x1 + 1; ++x) {
      gctx.moveTo(...toScreen([x - 0.5, cy0 - 0.5]));
      gctx.lineTo(...toScreen([x - 0.5, y1 + 0.5]));
    }
    for (let y = cy0; y <= y1 + 1; ++y) {
      gctx.moveTo(...toScreen([cx0 - 0.5, y - 0.5]));
      gctx.lineTo(...toScreen([x1 + 0.5, y - 0.5]));
    }
    gctx.stroke();
    if (z < 12) return;
    gctx.fillStyle = 'rgba(0,0,0,0.45)';
    const r = Math.max(1, z / 16);
    for (let y = cy0; y <= y1; ++y) {
      for (let x = cx0; x <= x1; ++x) {
        const [px, py] = toScreen([x, y]);
        gctx.fillRect(px - r, py - r, 2 * r, 2 * r);
      }
    }
  }

  function drawGrid() {
    gctx.setTransform(1, 0, 0, 1, 0, 0);
    gctx.clearRect(0, 0, grid.width, grid.height);
    placeFill();
    const z = view.zoom;
    if (diffPicture) {
      const c = document.createElement('canvas');
      c.width = diffPicture.width;
      c.height = diffPicture.height;
      c.getContext('2d').putImageData(new ImageData(diffPicture.rgba, diffPicture.width, diffPicture.height), 0, 0);
      gctx.imageSmoothingEnabled = false;
      gctx.drawImage(c, view.x - z / 2, view.y - z / 2, c.width * z, c.height * z);
    }
    if (z >= 6) drawPixelGrid(z);
    const step = currentStep();
    if (step && step.kind === 'scanlines') {
      // The current scanline through the pixel centres of its row: y = the row, where the
      // vertices at integer coordinates lie.
      gctx.strokeStyle = '#c00';
      gctx.lineWidth = 2;
      gctx.beginPath();
      const [, sy] = toScreen([0, step.last_row]);
      gctx.moveTo(view.x - z / 2, sy);
      gctx.lineTo(view.x + (fillCanvas.width - 0.5) * z, sy);
      gctx.stroke();
    }
    if (s.mode !== 'scene') {
      gctx.strokeStyle = '#000';
      gctx.lineWidth = 1.5;
      gctx.beginPath();
      vertices().forEach((v, i) => {
        const [px, py] = toScreen(v);
        if (i === 0) gctx.moveTo(px, py);
        else gctx.lineTo(px, py);
      });
      gctx.closePath();
      gctx.stroke();
      vertices().forEach((v, i) => {
        const [px, py] = toScreen(v);
        // A polygon's vertices take the command's default colours: red, green, blue, repeated.
        gctx.fillStyle = s.mode === 'triangle' ? toHex(s.colors[i]) : ['#ff0000', '#00ff00', '#0000ff'][i % 3];
        gctx.strokeStyle = '#000';
        gctx.beginPath();
        gctx.arc(px, py, handleRadius(), 0, 2 * Math.PI);
        gctx.fill();
        gctx.stroke();
      });
    }
    if (marked) {
      gctx.strokeStyle = '#f0f';
      gctx.lineWidth = 2;
      const [px, py] = toScreen([marked[0] - 0.5, marked[1] - 0.5]);
      gctx.strokeRect(px, py, Math.max(3, z), Math.max(3, z));
    }
  }

  function drawStep() {
    const n = plan.length;
    show('step-no', n ? `step ${s.step + 1} / ${n}` : 'no steps');
    const slider = $('slider');
    if (slider.max !== String(Math.max(0, n - 1))) slider.max = String(Math.max(0, n - 1));
    if (slider.value !== String(s.step)) slider.value = String(s.step);
    if (!n || !shownFrame) return;
    if (frame.width !== shownFrame.w || frame.height !== shownFrame.h) {
      frame.width = shownFrame.w;
      frame.height = shownFrame.h;
    }
    drawFrame(fctx, shownFrame);
    if (frame.dataset.step !== String(s.step)) frame.dataset.step = String(s.step);
  }

  function showTables() {
    const step = currentStep();
    show('step-kind', step ? stepTitle(step) : '');
    const row = step && step.kind === 'scanlines' && shown ? shown.scanline : null;
    // The step list, the sentence said and the labels follow the plan, but not on a drag's
    // mouse move (a screen reader would be told every move): the release writes them.
    if (!(drag && drag.vertex !== undefined)) {
      showStepList(plan, s.step);
      const sentence = step ? stepSentence(step, s.step, plan.length, row) : 'no steps';
      show('announce', sentence);
      const label = `the step's frame. ${sentence}`;
      if (frame.getAttribute('aria-label') !== label) frame.setAttribute('aria-label', label);
      if (grid.getAttribute('aria-label') !== gridLabel()) grid.setAttribute('aria-label', gridLabel());
      const title = `scantrace explorer: ${shownName()}${step ? `, step ${s.step + 1} of ${plan.length}` : ''}`;
      if (document.title !== title) document.title = title;
    }
    const table = shown && shown.edge_table;
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
    show('events', !shown ? ''
      : traceText === null ? `${shown.events} events (their JSON Lines written when the vertex is let go)`
        : `${shown.events} events, ${traceText.length} bytes of JSON Lines`);
  }

  // What the grid shows, in words: the page's title and the grid's label.
  const shownName = () => (s.mode === 'scene' ? `scene ${s.sceneName}` : `${s.mode} ${vertices().map((v) => `(${v.join(',')})`).join(' ')}`);
  function gridLabel() {
    const what = `the ${shownName()}`;
    const size = s.mode === 'scene' && fill ? [fill.width, fill.height] : s.size;
    return `the pixel grid: ${what}, ${size.join(' by ')} pixels${marked ? `, pixel (${marked.join(', ')}) marked` : ''}`;
  }

  function setStep(k) {
    s.step = Math.max(0, Math.min(plan.length - 1, k));
    try {
      composeStep();
    } catch (e) {
      showError(e);
    }
    redraw();
  }

  function why(x, y) {
    marked = [x, y];
    if (s.mode === 'polygon') {
      showWhy(null, '(why answers for a triangle or a scene: the pixel\u2019s spans are in the trace)');
      return redraw();
    }
    try {
      const story = st.why(s.mode === 'triangle' ? sceneObj : scene, x, y, fillOptions());
      showWhy(story);
      $('why').dataset.pixel = `${x},${y}`;
    } catch (e) {
      showError(e);
    }
    redraw();
  }

  // A pixel's why: the answer in a sentence, `scantrace why`'s text, its JSON behind a toggle.
  function showWhy(story, note = '') {
    const prose = story ? whyProse(story) : { answer: note, text: '' };
    $('why-answer').textContent = prose.answer;
    $('why').textContent = prose.text;
    $('why').hidden = !story;
    $('why-json').textContent = story ? JSON.stringify(story, null, 1) : '';
    $('why-json-box').hidden = !story;
  }

  // A diff's summary (verdict, the colours of the picture with their counts, the patterns), the
  // report's JSON written into its toggle only when opened: 80,000 lines for a wrong scene.
  let diffReport = null;
  function showDiff(report) {
    diffReport = report;
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
  $('diff-json-box').addEventListener('toggle', () => {
    if ($('diff-json-box').open && diffReport && !$('diff-json').textContent) $('diff-json').textContent = JSON.stringify(diffReport, null, 1);
  });

  // --- input -------------------------------------------------------------------------------
  function pointer(e) {
    const r = grid.getBoundingClientRect();
    return [(e.clientX - r.left) * (grid.width / r.width), (e.clientY - r.top) * (grid.height / r.height)];
  }
  const snap = (v) => {
    const g = 2 ** s.subpixel_bits;
    return Math.round(v * g) / g;
  };

  // Grid canvas pixels a CSS pixel (the grid's 720 pixels over its box: 2 on a phone).
  const canvasPerCss = () => grid.width / (gridBoxWidth || grid.width);
  // The handles: drawn at least 7 canvas (and 6 CSS) pixels wide in radius; taken within 12
  // CSS pixels of the vertex (a 24-pixel target), 18 for a finger.
  const handleRadius = () => Math.max(7, 6 * canvasPerCss());
  function vertexAt(px, py, touch) {
    const reach = Math.max(9, (touch ? 18 : 12) * canvasPerCss());
    let best = -1, bestDistance = reach;
    vertices().forEach((v, i) => {
      const d = Math.hypot(toScreen(v)[0] - px, toScreen(v)[1] - py);
      if (d <= bestDistance) [best, bestDistance] = [i, d];
    });
    return best;
  }

  // Pointer events: a mouse, a pen or a finger (the grid's touch-action: none keeps a finger's
  // drag from scrolling the page); the grid captures the pointer for the drag's length.
  grid.addEventListener('pointerdown', (e) => {
    if (e.button !== 0) return;
    grid.setPointerCapture(e.pointerId);
    const [px, py] = pointer(e);
    if (s.mode !== 'scene') {
      const i = vertexAt(px, py, e.pointerType === 'touch');
      if (s.mode === 'polygon' && e.altKey && i >= 0 && s.polygon.length > 3) {
        s.polygon.splice(i, 1);  // alt-click: the vertex removed
        return recompute();
      }
      if (s.mode === 'polygon' && e.shiftKey && i < 0) {
        const [x, y] = toCanvas(px, py);
        s.polygon.push([snap(x), snap(y)]);  // shift-click: a vertex added after the last
        return recompute();
      }
      if (i >= 0) {
        drag = { vertex: i };
        return;
      }
    }
    drag = { pan: [px, py, view.x, view.y], moved: false };
  });
  grid.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const [px, py] = pointer(e);
    if (drag.vertex !== undefined) {
      const [x, y] = toCanvas(px, py);
      vertices()[drag.vertex] = [snap(x), snap(y)];
      // While dragging, everything follows the mouse: the fill, the trace, the tables and the
      // composed frame of the current step. The handler's time, kept for the bench
      // (web/bench/explorer_drag.mjs) and the test's report.
      const t0 = performance.now();
      recompute(true);
      dragTimes.push(performance.now() - t0);
      dragStages.push(lastStages);
    } else {
      const [x0, y0, vx, vy] = drag.pan;
      if (Math.hypot(px - x0, py - y0) > 3) drag.moved = true;
      view.x = vx + px - x0;
      view.y = vy + py - y0;
      drawGrid();
    }
  });
  grid.addEventListener('pointercancel', () => {
    if (drag && drag.vertex !== undefined) recompute();
    drag = null;
  });
  grid.addEventListener('pointerup', (e) => {
    if (drag && drag.vertex !== undefined) {
      drag = null;
      recompute(); // the trace's JSON Lines too, and the address
    }
    if (drag && drag.pan && !drag.moved) {
      const [x, y] = pixelAt(...pointer(e));
      if (fill && x >= 0 && y >= 0 && x < fill.width && y < fill.height) why(x, y);
    }
    drag = null;
  });
  grid.addEventListener('wheel', (e) => {
    e.preventDefault();
    const [px, py] = pointer(e);
    const [cx, cy] = toCanvas(px, py);
    view.zoom = Math.max(0.25, Math.min(64, view.zoom * (e.deltaY < 0 ? 1.25 : 0.8)));
    view.x = px - cx * view.zoom;
    view.y = py - cy * view.zoom;
    drawGrid();
  }, { passive: false });

  function bindOption(id, key, parse = (v) => v) {
    const el = $(id);
    el.value = String(s[key]);
    el.addEventListener('change', () => {
      s[key] = parse(el.value);
      recompute();
    });
  }
  bindOption('shading', 'shading');
  bindOption('fill-rule', 'fill_rule');
  bindOption('method', 'method');
  bindOption('bits', 'subpixel_bits', Number);
  bindOption('winding', 'winding');
  $('rows').value = String(s.rows_per_step);
  bindPlayer({
    plan: () => plan,
    step: () => s.step,
    setStep,
    setRows: (n) => {
      s.rows_per_step = n;
      recompute();
    },
    link: () => {
      history.replaceState(null, '', toHash(s));
      return location.href;
    },
    present,
  });
  $('present').addEventListener('click', () => present(!document.body.classList.contains('presenting')));
  // Presentation: the frame alone (the page's CSS), full screen where the browser lets the page;
  // leaving full screen (Esc, which the browser takes) leaves it too. The frame's box resized,
  // the ResizeObserver below composes it again at its new size.
  function present(on) {
    if (on === document.body.classList.contains('presenting')) return;
    document.body.classList.toggle('presenting', on);
    $('present').setAttribute('aria-pressed', String(on));
    if (on && document.fullscreenEnabled && !document.fullscreenElement) document.documentElement.requestFullscreen().catch(() => {});
    if (!on && document.fullscreenElement) document.exitFullscreen().catch(() => {});
  }
  document.addEventListener('fullscreenchange', () => {
    if (!document.fullscreenElement) present(false);
  });
  [0, 1, 2].forEach((i) => {
    const el = $(`color${i}`);
    el.value = toHex(s.colors[i]);
    el.addEventListener('input', () => {
      s.colors[i] = fromHex(el.value);
      recompute();
    });
  });
  $('triangle-mode').addEventListener('click', () => {
    awaitScene(null);
    s.mode = 'triangle';
    diffPicture = null;
    fitView();
    recompute();
  });
  $('polygon-mode').addEventListener('click', () => {
    awaitScene(null);
    s.mode = 'polygon';
    diffPicture = null;
    fitView();
    recompute();
  });
  $('demo-scene').addEventListener('click', () => {
    awaitScene(null);
    openScene({ name: 'demo_scene.json', data: st.demoScene() });
  });
  $('open').addEventListener('change', () => $('open').files[0] && openFile($('open').files[0]));

  // step: the step to show (a link's, once its scene is opened), else the first.
  function openScene(sc, step = 0) {
    scene = sc;
    s.mode = 'scene';
    s.sceneName = sc.name;
    s.step = step;
    diffPicture = null;
    recompute();
    fitView();
    redraw();
  }

  async function openFile(file) {
    const bytes = new Uint8Array(await file.arrayBuffer());
    if (/\.(json|obj)$/i.test(file.name)) {
      // The scene a link named, opened by hand: at the link's step.
      const step = awaited ? awaited.step : 0;
      awaitScene(null);
      openScene({ name: file.name, data: bytes }, step);
    }
    else if (/\.(png|npy)$/i.test(file.name)) await diffImage(file, bytes);
    else showError(`${file.name}: drop a scene (.json, .obj) or an image rendered for it (.png, .npy)`);
  }

  // A dropped image against the open scene. The module first checks it as `scantrace diff` does
  // before decoding (a PNG declaring 100000x100000 pixels, a truncated one, a .npy holding a
  // pickle: the command's line); a .npy it then decodes itself, a PNG the browser decodes.
  async function diffImage(file, bytes) {
    if (s.mode !== 'scene') return showError(`${file.name}: open the scene it was rendered for first`);
    try {
      const header = st.checkImage({ name: file.name, data: bytes });
      let report;
      if (header.format === 'npy') {
        report = st.diff(scene, { name: file.name, data: bytes }, fillOptions());
      } else {
        const bitmap = await createImageBitmap(new Blob([bytes], { type: `image/${header.format}` }));
        const c = document.createElement('canvas');
        c.width = bitmap.width;
        c.height = bitmap.height;
        const ctx = c.getContext('2d');
        ctx.drawImage(bitmap, 0, 0);
        const img = ctx.getImageData(0, 0, c.width, c.height);
        report = st.diff(scene, { width: c.width, height: c.height, rgba: img.data, name: file.name }, { ...fillOptions(), format: header.format });
      }
      diffPicture = st.lastDiffPicture;
      showDiff(report);
      showError(null);
      redraw();
    } catch (e) {
      showError(e.status ? e : `${file.name}: cannot decode the image`);
    }
  }

  document.addEventListener('dragover', (e) => e.preventDefault());
  document.addEventListener('drop', (e) => {
    e.preventDefault();
    if (e.dataTransfer.files[0]) openFile(e.dataTransfer.files[0]);
  });
  // The frame's box resized (a window resized, a projector, a scroll bar come or gone): the frame
  // composed again at its new size.
  new ResizeObserver((entries) => {
    gridBoxWidth = entries[entries.length - 1].contentRect.width;
    placeFill();
  }).observe(grid);
  new ResizeObserver((entries) => {
    frameBoxWidth = entries[entries.length - 1].contentRect.width;
    const { width, height } = frameSize();
    if (plan.length && (width !== frame.width || height !== frame.height)) setStep(s.step);
  }).observe(frame);
  window.addEventListener('hashchange', () => {
    if (location.hash === toHash(s)) return;
    s = fromHash(location.hash);
    openAddress();
  });

  // A link's scene: the demo is built in; a file the page cannot read by itself (opened from
  // file://, a page may not read other files), so the link says which file to drop, and the
  // page shows the triangle meanwhile, leaving the address as it came (the step kept).
  function openAddress() {
    if (s.mode !== 'scene') {
      awaitScene(null);
      fitView();
      return recompute();
    }
    if (['demo', 'demo_scene.json'].includes(s.sceneName)) {
      awaitScene(null);
      return openScene({ name: 'demo_scene.json', data: st.demoScene() }, s.step);
    }
    awaitScene({ name: s.sceneName, step: s.step, hash: location.hash });
    s.mode = 'triangle';
    s.step = 0;
    fitView();
    recompute();
  }
  function awaitScene(a) {
    awaited = a;
    const el = $('notice');
    el.hidden = !a;
    el.textContent = a
      ? `This link shows the scene \u201c${a.name}\u201d at step ${a.step + 1}, but a page cannot open a file by itself. ` +
        `Drop ${a.name} on the page (or choose it with \u201copen\u201d) to see it at that step. Meanwhile: the explorer\u2019s triangle.`
      : '';
  }
  openAddress();
  // For the console and the page's test (web/tests/chromium_explorer.mjs): where things are.
  window.explorer = {
    state: () => structuredClone(s),
    vertexOnScreen: (i) => {
      const r = grid.getBoundingClientRect();
      const [px, py] = toScreen(vertices()[i]);
      return [r.left + px * (r.width / grid.width), r.top + py * (r.height / grid.height)];
    },
    pixelOnScreen: (x, y) => {
      const r = grid.getBoundingClientRect();
      const [px, py] = toScreen([x, y]);
      return [r.left + px * (r.width / grid.width), r.top + py * (r.height / grid.height)];
    },
    traceText: () => traceText,
    // Milliseconds of each mouse move of a vertex drag so far (the handler: module and drawing).
    dragTimes: () => dragTimes.slice(),
    // Each move's stages, ms from the handler's start to the end of: the traced fill, the fill
    // put on its canvas, the step's frame composed, the grid drawn, the frame drawn, everything
    // drawn (the tables last).
    dragStages: () => dragStages.slice(),
    scene: () => (s.mode === 'triangle' ? JSON.stringify(triangleScene()) : null),
    // The module (the JavaScript API) and the frame shown, for the console and the test.
    module: () => st,
    // The frame's size as composed (the `frames` options width and height the page passes).
    frameSize: () => ({ width: frame.width, height: frame.height }),
    framePixels: () => Array.from(fctx.getImageData(0, 0, frame.width, frame.height).data),
    fillPixels: () => Array.from(fillCanvas.getContext('2d').getImageData(0, 0, fillCanvas.width, fillCanvas.height).data),
  };
  // Milliseconds from navigation to a working page (the test prints it; docs/performance.md).
  document.body.dataset.readyMs = performance.now().toFixed(0);
  document.body.dataset.ready = '1';
}
