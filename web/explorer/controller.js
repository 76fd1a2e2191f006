// The explorer's controller (docs/web.md): the input. A pointer (mouse, pen, finger) drags a
// vertex, pans or picks a pixel; the wheel zooms; the bar's options, the modes, files (chosen or
// dropped), the address and presentation mode change the state (state.js) and run the model;
// the player's keys are controls.js's. The explorer's modules share one scope in the page
// (make_page.mjs): names are unique across them.
import { ex, fillOptions, frameSize, fromHash, fromHex, namedOptions, recompute, setStep, toHash, toHex, triangleScene, vertices } from './state.js';
import { $, canvasPerCss, drawGrid, fitView, pixelAt, placeFill, redraw, showDiff, showError, showWhy, toCanvas, toScreen } from './view.js';
import { bindPlayer } from './controls.js';

export function why(x, y) {
  ex.marked = [x, y];
  if (ex.s.mode === 'polygon') {
    showWhy(null, '', '(why answers for a triangle or a scene: the pixel\u2019s spans are in the trace)');
    return redraw();
  }
  try {
    const story = ex.st.why(ex.s.mode === 'triangle' ? ex.sceneObj : ex.scene, x, y, fillOptions());
    showWhy(story, ex.st.lastWhyText);
    $('why').dataset.pixel = `${x},${y}`;
  } catch (e) {
    showError(e);
  }
  redraw();
}

export function pointer(e) {
  const r = ex.grid.getBoundingClientRect();
  return [(e.clientX - r.left) * (ex.grid.width / r.width), (e.clientY - r.top) * (ex.grid.height / r.height)];
}

export const snap = (v) => {
  const g = 2 ** ex.s.subpixel_bits;
  return Math.round(v * g) / g;
};

// A vertex within 12 CSS pixels of the point (a 24-pixel target), 18 for a finger: the nearest.
export function vertexAt(px, py, touch) {
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
export function onPointerDown(e) {
  if (e.button !== 0) return;
  ex.grid.setPointerCapture(e.pointerId);
  const [px, py] = pointer(e);
  if (ex.s.mode !== 'scene') {
    const i = vertexAt(px, py, e.pointerType === 'touch');
    if (ex.s.mode === 'polygon' && e.altKey && i >= 0 && ex.s.polygon.length > 3) {
      ex.s.polygon.splice(i, 1);  // alt-click: the vertex removed
      return recompute();
    }
    if (ex.s.mode === 'polygon' && e.shiftKey && i < 0) {
      const [x, y] = toCanvas(px, py);
      ex.s.polygon.push([snap(x), snap(y)]);  // shift-click: a vertex added after the last
      return recompute();
    }
    if (i >= 0) {
      ex.drag = { vertex: i };
      return;
    }
  }
  ex.drag = { pan: [px, py, ex.view.x, ex.view.y], moved: false };
}

export function onPointerMove(e) {
  if (!ex.drag) return;
  const [px, py] = pointer(e);
  if (ex.drag.vertex !== undefined) {
    const [x, y] = toCanvas(px, py);
    vertices()[ex.drag.vertex] = [snap(x), snap(y)];
    // While dragging, everything follows the mouse: the fill, the trace, the tables and the
    // composed frame of the current step. The handler's time, kept for the bench
    // (web/bench/explorer_drag.mjs) and the test's report.
    const t0 = performance.now();
    recompute(true);
    ex.dragTimes.push(performance.now() - t0);
    ex.dragStages.push(ex.lastStages);
  } else {
    const [x0, y0, vx, vy] = ex.drag.pan;
    if (Math.hypot(px - x0, py - y0) > 3) ex.drag.moved = true;
    ex.view.x = vx + px - x0;
    ex.view.y = vy + py - y0;
    drawGrid();
  }
}

export function onPointerUp(e) {
  if (ex.drag && ex.drag.vertex !== undefined) {
    ex.drag = null;
    recompute(); // the trace's JSON Lines too, and the address
  }
  if (ex.drag && ex.drag.pan && !ex.drag.moved) {
    const [x, y] = pixelAt(...pointer(e));
    if (ex.fill && x >= 0 && y >= 0 && x < ex.fill.width && y < ex.fill.height) why(x, y);
  }
  ex.drag = null;
}

export function onWheel(e) {
  e.preventDefault();
  const [px, py] = pointer(e);
  const [cx, cy] = toCanvas(px, py);
  ex.view.zoom = Math.max(0.25, Math.min(64, ex.view.zoom * (e.deltaY < 0 ? 1.25 : 0.8)));
  ex.view.x = px - cx * ex.view.zoom;
  ex.view.y = py - cy * ex.view.zoom;
  drawGrid();
}

export function bindPointer() {
  ex.grid.addEventListener('pointerdown', onPointerDown);
  ex.grid.addEventListener('pointermove', onPointerMove);
  ex.grid.addEventListener('pointerup', onPointerUp);
  ex.grid.addEventListener('pointercancel', () => {
    if (ex.drag && ex.drag.vertex !== undefined) recompute();
    ex.drag = null;
  });
  ex.grid.addEventListener('wheel', onWheel, { passive: false });
}

export function bindOption(id, key, parse = (v) => v) {
  const el = $(id);
  // A named option's choices are its table's names, as the module gives them (state.js).
  if (key in namedOptions) el.replaceChildren(...ex.st.optionTable()[namedOptions[key]].names.map((n) => new Option(n)));
  el.value = String(ex.s[key]);
  el.addEventListener('change', () => {
    ex.s[key] = parse(el.value);
    recompute();
  });
}

// The bar's options and the player (controls.js), each change run through the module.
export function bindOptions() {
  bindOption('shading', 'shading');
  bindOption('fill-rule', 'fill_rule');
  bindOption('method', 'method');
  bindOption('bits', 'subpixel_bits', Number);
  bindOption('winding', 'winding');
  $('rows').value = String(ex.s.rows_per_step);
  bindPlayer({
    plan: () => ex.plan,
    step: () => ex.s.step,
    setStep,
    setRows: (n) => {
      ex.s.rows_per_step = n;
      recompute();
    },
    link: () => {
      history.replaceState(null, '', toHash(ex.s));
      return location.href;
    },
    present,
  });
}

// Presentation: the frame alone (the page's CSS), full screen where the browser lets the page;
// leaving full screen (Esc, which the browser takes) leaves it too. The frame's box resized,
// the ResizeObserver below composes it again at its new size.
export function present(on) {
  if (on === document.body.classList.contains('presenting')) return;
  document.body.classList.toggle('presenting', on);
  $('present').setAttribute('aria-pressed', String(on));
  if (on && document.fullscreenEnabled && !document.fullscreenElement) document.documentElement.requestFullscreen().catch(() => {});
  if (!on && document.fullscreenElement) document.exitFullscreen().catch(() => {});
}

export function bindPresent() {
  $('present').addEventListener('click', () => present(!document.body.classList.contains('presenting')));
  document.addEventListener('fullscreenchange', () => {
    if (!document.fullscreenElement) present(false);
  });
}

// The vertex colours and the modes (triangle, polygon, the demo scene, a file).
export function bindModes() {
  [0, 1, 2].forEach((i) => {
    const el = $(`color${i}`);
    el.value = toHex(ex.s.colors[i]);
    el.addEventListener('input', () => {
      ex.s.colors[i] = fromHex(el.value);
      recompute();
    });
  });
  for (const mode of ['triangle', 'polygon']) {
    $(`${mode}-mode`).addEventListener('click', () => {
      awaitScene(null);
      ex.s.mode = mode;
      ex.diffPicture = null;
      fitView();
      recompute();
    });
  }
  $('demo-scene').addEventListener('click', () => {
    awaitScene(null);
    openScene({ name: 'demo_scene.json', data: ex.st.demoScene() });
  });
  $('open').addEventListener('change', () => $('open').files[0] && openFile($('open').files[0]));
}

// step: the step to show (a link's, once its scene is opened), else the first.
export function openScene(sc, step = 0) {
  ex.scene = sc;
  ex.s.mode = 'scene';
  ex.s.sceneName = sc.name;
  ex.s.step = step;
  ex.diffPicture = null;
  recompute();
  fitView();
  redraw();
}

export async function openFile(file) {
  const bytes = new Uint8Array(await file.arrayBuffer());
  if (/\.(json|obj)$/i.test(file.name)) {
    // The scene a link named, opened by hand: at the link's step.
    const step = ex.awaited ? ex.awaited.step : 0;
    awaitScene(null);
    openScene({ name: file.name, data: bytes }, step);
  }
  else if (/\.(png|npy)$/i.test(file.name)) await diffImage(file, bytes);
  else showError(`${file.name}: drop a scene (.json, .obj) or an image rendered for it (.png, .npy)`);
}

// A dropped image against the open scene. The module first checks it as `scantrace diff` does
// before decoding (a PNG declaring 100000x100000 pixels, a truncated one, a .npy holding a
// pickle: the command's line); a .npy it then decodes itself, a PNG the browser decodes.
export async function diffImage(file, bytes) {
  if (ex.s.mode !== 'scene') return showError(`${file.name}: open the scene it was rendered for first`);
  try {
    // Checked against the open scene: a size other than its canvas's is answered from the
    // header (canvas_size), as the command answers it, and nothing is decoded.
    const header = ex.st.checkImage({ name: file.name, data: bytes }, ex.scene, fillOptions());
    let report = header.report;
    if (report) {
      // nothing to decode
    } else if (header.format === 'npy') {
      report = ex.st.diff(ex.scene, { name: file.name, data: bytes }, fillOptions());
    } else {
      const bitmap = await createImageBitmap(new Blob([bytes], { type: `image/${header.format}` }));
      const c = document.createElement('canvas');
      c.width = bitmap.width;
      c.height = bitmap.height;
      const ctx = c.getContext('2d');
      ctx.drawImage(bitmap, 0, 0);
      const img = ctx.getImageData(0, 0, c.width, c.height);
      report = ex.st.diff(ex.scene, { width: c.width, height: c.height, rgba: img.data, name: file.name }, { ...fillOptions(), format: header.format });
    }
    ex.diffPicture = ex.st.lastDiffPicture;
    showDiff(report);
    showError(null);
    redraw();
  } catch (e) {
    showError(e.status ? e : `${file.name}: cannot decode the image`);
  }
}

// A file dropped, the boxes resized, the address changed by hand.
export function bindWindow() {
  document.addEventListener('dragover', (e) => e.preventDefault());
  document.addEventListener('drop', (e) => {
    e.preventDefault();
    if (e.dataTransfer.files[0]) openFile(e.dataTransfer.files[0]);
  });
  // The frame's box resized (a window resized, a projector, a scroll bar come or gone): the frame
  // composed again at its new size.
  new ResizeObserver((entries) => {
    ex.gridBoxWidth = entries[entries.length - 1].contentRect.width;
    placeFill();
  }).observe(ex.grid);
  new ResizeObserver((entries) => {
    ex.frameBoxWidth = entries[entries.length - 1].contentRect.width;
    const { width, height } = frameSize();
    if (ex.plan.length && (width !== ex.frame.width || height !== ex.frame.height)) setStep(ex.s.step);
  }).observe(ex.frame);
  window.addEventListener('hashchange', () => {
    if (location.hash === toHash(ex.s)) return;
    ex.s = fromHash(location.hash);
    openAddress();
  });
}

// A link's scene: the demo is built in; a file the page cannot read by itself (opened from
// file://, a page may not read other files), so the link says which file to drop, and the
// page shows the triangle meanwhile, leaving the address as it came (the step kept).
export function openAddress() {
  if (ex.s.mode !== 'scene') {
    awaitScene(null);
    fitView();
    return recompute();
  }
  if (['demo', 'demo_scene.json'].includes(ex.s.sceneName)) {
    awaitScene(null);
    return openScene({ name: 'demo_scene.json', data: ex.st.demoScene() }, ex.s.step);
  }
  awaitScene({ name: ex.s.sceneName, step: ex.s.step, hash: location.hash });
  ex.s.mode = 'triangle';
  ex.s.step = 0;
  fitView();
  recompute();
}

export function awaitScene(a) {
  ex.awaited = a;
  const el = $('notice');
  el.hidden = !a;
  el.textContent = a
    ? `This link shows the scene \u201c${a.name}\u201d at step ${a.step + 1}, but a page cannot open a file by itself. ` +
      `Drop ${a.name} on the page (or choose it with \u201copen\u201d) to see it at that step. Meanwhile: the explorer\u2019s triangle.`
    : '';
}

// For the console and the page's test (web/tests/chromium_explorer.mjs): where things are.
export function exposeForTests() {
  window.explorer = {
    state: () => structuredClone(ex.s),
    vertexOnScreen: (i) => {
      const r = ex.grid.getBoundingClientRect();
      const [px, py] = toScreen(vertices()[i]);
      return [r.left + px * (r.width / ex.grid.width), r.top + py * (r.height / ex.grid.height)];
    },
    pixelOnScreen: (x, y) => {
      const r = ex.grid.getBoundingClientRect();
      const [px, py] = toScreen([x, y]);
      return [r.left + px * (r.width / ex.grid.width), r.top + py * (r.height / ex.grid.height)];
    },
    traceText: () => ex.traceText,
    // Milliseconds of each mouse move of a vertex drag so far (the handler: module and drawing).
    dragTimes: () => ex.dragTimes.slice(),
    // Each move's stages, ms from the handler's start to the end of: the traced fill, the fill
    // put on its canvas, the step's frame composed, the grid drawn, the frame drawn, everything
    // drawn (the tables last).
    dragStages: () => ex.dragStages.slice(),
    scene: () => (ex.s.mode === 'triangle' ? JSON.stringify(triangleScene()) : null),
    // The module (the JavaScript API) and the frame shown, for the console and the test.
    module: () => ex.st,
    // The frame's size as composed (the `frames` options width and height the page passes).
    frameSize: () => ({ width: ex.frame.width, height: ex.frame.height }),
    framePixels: () => Array.from(ex.fctx.getImageData(0, 0, ex.frame.width, ex.frame.height).data),
    fillPixels: () => Array.from(ex.fillCanvas.getContext('2d').getImageData(0, 0, ex.fillCanvas.width, ex.fillCanvas.height).data),
  };
}
