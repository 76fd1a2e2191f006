// The trace page (docs/web.md): `replay`/`explain -o OUT.html` write the trace and this player,
// which composes each step's frame in the page with its WebAssembly module (player_api.mjs: the
// composer of the videos, and nothing the page does not call) and draws it with the canvas
// backend (frame_draw.js), sharp at any size: kilobytes of trace instead of megabytes of
// pre-drawn frames. The frame is fitted to the window; the step list is beside it, hidden until
// asked for. Keys, play and its speed, g and the help are the player core's (controller.mjs,
// bind.mjs, keys.json). OUT.html#step=N opens at step N (from 1).
/* global drawScantraceFrame, SCANTRACE_KEYS */
import { bindPlayer } from './bind.mjs';
import { createStepper } from './controller.mjs';
import { playerKeys } from './keys.mjs';

// pm: loadPlayer()'s module; cfg: {source, width, height, rows_per_step, mode, first, last, marked_pixel?}
export async function startPlayer(pm, cfg, traceText) {
  const $ = (id) => document.getElementById(id);
  const plan = planner(pm, cfg, traceText);
  const events = traceText.split('\n').filter((l) => l).map((l) => JSON.parse(l));
  const canvas = $('frame');
  let steps = plan.steps(cfg.rows_per_step);
  const say = (text) => { $('status').textContent = text; };
  const drawer = canvasDrawer(pm, plan, cfg, canvas, () => s);
  const s = createStepper({ count: steps.length, show: drawer.show, rows: rowsOf(steps), say, speed: 2.5 });
  const relist = () => {
    $('list').replaceChildren(...steps.map((st, i) => {
      const el = document.createElement('div');
      el.textContent = `${i + 1}. ${label(st)}`;
      el.addEventListener('click', () => s.go(i));
      return el;
    }));
  };
  // r: one row a step, ten, or the planned steps; the step kept where its rows still are.
  const rowChoices = [cfg.rows_per_step || 0, 1, 10].filter((v, i, a) => a.indexOf(v) === i);
  let rowChoice = 0;
  function toggleRows() {
    const row = steps[s.index].kind === 'scanlines' ? steps[s.index].first_row : null;
    rowChoice = (rowChoice + 1) % rowChoices.length;
    steps = plan.steps(rowChoices[rowChoice]);
    drawer.forget();
    s.rows = rowsOf(steps);
    relist();
    const at = row === null ? -1 : steps.findIndex((st) => st.kind === 'scanlines' && st.first_row <= row && row <= st.last_row);
    s.resize(steps.length, at >= 0 ? at : Math.round(s.index * steps.length / s.count));
    say(rowChoices[rowChoice] ? `${rowChoices[rowChoice]} scanline${rowChoices[rowChoice] > 1 ? 's' : ''} a step` : 'steps as planned');
  }
  relist();
  const keys = playerKeys(SCANTRACE_KEYS, 'trace');
  // The hint under the frame: a few of the key table's rows (? shows them all).
  $('info').textContent = `${keys.hint(['next', 'previous', 'go_to_row', 'play', 'help'])} \u00b7 click a pixel of the canvas for its row in the trace`;
  bindPlayer(s, {
    scope: document, keys, first: 1, slider: $('slider'),
    counter: $('step-no'), counterText: () => `step ${s.index + 1} / ${s.count}: ${label(steps[s.index])}`,
    list: $('list'), playButton: $('play'), speed: $('speed'), help: $('help'), hash: true, say,
    announce: $('announce'), actions: { toggle_rows: toggleRows },
  });
  canvas.addEventListener('click', (e) => {
    $('info').textContent = pixelStory(e, canvas, cfg, steps[s.index], events, $('info')) || $('info').textContent;
  });
  $('toggle-list').addEventListener('click', () => {
    $('list').hidden = !$('list').hidden;
    drawer.fit();
    s.go(s.index);
  });
  window.addEventListener('resize', () => {
    drawer.fit();
    s.go(s.index);
  });
  drawer.fit();
  s.go(s.initialIndex);
  // Milliseconds from navigation to a working page (the test prints it; docs/performance.md).
  document.body.dataset.readyMs = performance.now().toFixed(0);
  document.body.dataset.ready = '1';
}

// A phone's width (player.html's one-column layout, under 700 px): the controls wrap, nothing
// is wider than the screen but the frame, which is drawn wide enough for its smallest text to
// read at 10 CSS px, in a box that scrolls sideways; the step list goes under it.
const narrow = () => window.matchMedia('(max-width: 700px)').matches;

// The scale (CSS pixels a frame pixel) at which frame f's smallest text reads as a 10.5-px font:
// of its texts holding a capital or a digit, the shortest one's tallest glyph (its strokes'
// extent) as a sans-serif's capitals, 0.7 of its font size.
function readableScale(f) {
  let smallest = Infinity;
  for (const op of f.ops) {
    if (op[0] !== 'G' || !/[A-Z0-9]/.test(op[3])) continue;
    let most = 0;
    for (let k = 0; k < op[6].length; k += 3) {
      const ys = f.glyphs[op[6][k]].flatMap((stroke) => stroke.filter((v, i) => i % 2 === 1));
      if (ys.length) most = Math.max(most, Math.max(...ys) - Math.min(...ys));
    }
    if (most > 0) smallest = Math.min(smallest, most);
  }
  return smallest < Infinity ? (10.5 * 0.7) / smallest : 0;
}

// The canvas's drawing: fit() sizes it to the stage, show(i) draws step i when it is still the
// stepper's (`stepper()`), forget() drops the frame composed ahead (the steps planned again).
// The frame is drawn at the size it is shown, in device pixels: sharp at any zoom. On a phone
// it is as wide as the stage or as its smallest text needs (the most any step shown needed, so
// the frame does not change size back and forth), the stage scrolling sideways.
function canvasDrawer(pm, plan, cfg, canvas, stepper) {
  const ctx = canvas.getContext('2d');
  let drawing = Promise.resolve(), scale = 1, readable = 0;
  // The next step's frame is composed ahead, once the shown one is drawn: stepping on, the
  // common case, then only draws (composing a course triangle's frame is most of a step's time).
  let ahead = null; // {index, frame}
  const frameOf = (i) => (ahead && ahead.index === i ? ahead.frame : pm.frame(plan.first + i));
  const composeAhead = (i) => setTimeout(() => {
    const s = stepper();
    if (s.index === i - 1 && i < s.count && !(ahead && ahead.index === i)) ahead = { index: i, frame: pm.frame(plan.first + i) };
  }, 0);
  const drawer = {
    fit() {
      const stage = document.getElementById('stage');
      scale = narrow() ? Math.max(stage.clientWidth / cfg.width, readable)
        : Math.min(stage.clientWidth / cfg.width, stage.clientHeight / cfg.height);
      canvas.style.width = `${Math.floor(cfg.width * scale)}px`;
      canvas.style.height = `${Math.floor(cfg.height * scale)}px`;
    },
    forget: () => { ahead = null; },
    show(wanted) {
      drawing = drawing.then(async () => {
        if (wanted !== stepper().index) return;
        const t0 = performance.now();
        const f = frameOf(wanted);
        const t1 = performance.now();
        const needs = narrow() ? readableScale(f) * cfg.width / f.w : 0;
        if (needs > readable) {
          readable = needs;
          drawer.fit();
        }
        const dpr = window.devicePixelRatio || 1;
        canvas.width = Math.round(cfg.width * scale * dpr);
        canvas.height = Math.round(cfg.height * scale * dpr);
        ctx.setTransform(canvas.width / f.w, 0, 0, canvas.height / f.h, 0, 0);
        await drawScantraceFrame(ctx, f);
        canvas.dataset.step = String(wanted);
        // For the tests and anyone timing the page: composing (0 when composed ahead), drawing.
        canvas.dataset.composeMs = (t1 - t0).toFixed(1);
        canvas.dataset.drawMs = (performance.now() - t1).toFixed(1);
        composeAhead(wanted + 1);
      });
    },
  };
  return drawer;
}

// The trace opened with `rows_per_step` (0: as planned), its steps cfg.first..cfg.last when
// planned as the page was written, all of them otherwise. `first`: the module's index of step 1.
function planner(pm, cfg, traceText) {
  const base = { width: cfg.width, height: cfg.height, source: cfg.source };
  if (cfg.mode) base.mode = cfg.mode;
  if (cfg.marked_pixel) base.marked_pixel = cfg.marked_pixel;
  const p = {
    first: 0,
    steps(rowsPerStep) {
      const all = pm.open(traceText, { ...base, rows_per_step: rowsPerStep || 0 }).steps;
      const planned = (rowsPerStep || 0) === (cfg.rows_per_step || 0);
      p.first = planned ? Math.min(cfg.first || 0, all.length - 1) : 0;
      const last = planned ? Math.min(cfg.last ?? all.length - 1, all.length - 1) : all.length - 1;
      return all.slice(p.first, last + 1);
    },
  };
  return p;
}

const rowsOf = (steps) => steps.map((st) => (st.kind === 'scanlines' ? [st.first_row, st.last_row] : null));

function label(s) {
  return s.kind === 'scanlines' ? `rows ${s.first_row}..${s.last_row} of triangle ${s.triangle}`
    : s.triangle >= 0 ? `${s.kind.replace(/_/g, ' ')}, triangle ${s.triangle}` : s.kind.replace(/_/g, ' ');
}

// A click on the canvas: the pixel under it and what the trace says of its row (null: outside
// the step's grid). The pixel is kept on `info` for tests.
function pixelStory(e, canvas, cfg, step, events, info) {
  if (!step.view) return null;
  const r = canvas.getBoundingClientRect();
  const u = (e.clientX - r.left) / r.width * cfg.width, v = (e.clientY - r.top) / r.height * cfg.height;
  const [vx, vy, vw, vh] = step.view;
  if (u < vx || v < vy || u >= vx + vw || v >= vy + vh) return null;
  const x = Math.round((u - step.origin[0]) / step.cell), y = Math.round((v - step.origin[1]) / step.cell);
  const parts = events.filter((ev) => ev.type === 'scanline' && ev.y === y).map((ev) => {
    const spans = ev.spans || (ev.span ? [ev.span] : []);
    const inside = spans.some((sp) => sp.x_begin <= x && x < sp.x_end);
    return `triangle ${ev.triangle}: ${spans.map((sp) => `[${sp.x_begin}, ${sp.x_end})`).join(' ') || 'no span'} → ${inside ? 'filled' : 'not filled'}`;
  });
  info.dataset.pixel = `${x},${y}`;
  return `pixel (${x}, ${y}): ${parts.join('; ') || 'no traced row'}`;
}
