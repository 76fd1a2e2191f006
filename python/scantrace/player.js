// The inline trace player of the scantrace Python package (Trace._repr_html_, _player.py): a
// <canvas> that draws one frame of a deck (python/src/player_deck.hpp) at a time through the
// canvas backend's drawScantraceFrame (viz/frame_json.hpp, inserted before this script), with
// buttons, a slider and the keys of the command's HTML player. Nothing is loaded from anywhere:
// the deck is in the page.

// The deck's op `i` as canvas JSON ops (frame_json.hpp's format): text gets its Hershey strokes,
// a line group its lines, a patch of pixels the block it patches.
function scantraceExpandOp(deck, i, cache) {
  if (cache.has(i)) return cache.get(i);
  const op = deck.ops[i];
  let out;
  if (op[0] === 't') {
    const [, clip, mark, text, colour, thickness, font, scale, x, y] = op;
    out = [['T', clip, mark, text, colour, thickness,
            scantraceHersheyStrokes(deck.glyphs[font], text, scale, x, y)]];
  } else if (op[0] === 'l') {
    const [, clip, mark, colour, thickness, shift, chains] = op;
    const s = 1 / (1 << shift);
    out = [];
    for (const c of chains)
      for (let k = 0; k + 3 < c.length; k += 2)
        out.push(['L', clip, mark, c[k] * s, c[k + 1] * s, c[k + 2] * s, c[k + 3] * s, colour,
                  thickness]);
  } else if (op[0] === 'p') {
    // The earlier block (without its mark: this op carries the block's mark), then the patch.
    out = scantraceExpandOp(deck, op[8], cache).map((o) => [o[0], o[1], null].concat(o.slice(3)));
    out.push(['P'].concat(op.slice(1, 8)));
  } else {
    out = [op];
  }
  cache.set(i, out);
  return out;
}

// viz::hershey_strokes (viz/hershey.cpp) in the same floating-point steps: the strokes of `text`
// drawn from (x, y) on the baseline, as flat [x0, y0, x1, y1, ...] polylines.
function scantraceHersheyStrokes(glyphs, text, scale, x0, y0) {
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

// Frame `k` of the deck as a canvas JSON frame.
function scantraceDeckFrame(deck, k, cache) {
  const ops = [];
  const runs = deck.frames[k];
  for (let r = 0; r < runs.length; r += 2)
    for (let i = runs[r]; i < runs[r] + runs[r + 1]; ++i)
      for (const o of scantraceExpandOp(deck, i, cache)) ops.push(o);
  return {w: deck.w, h: deck.h, bg: deck.bg, ops: ops};
}

function scantracePlayer(root, deck) {
  const canvas = root.querySelector('canvas');
  const ctx = canvas.getContext('2d');
  const slider = root.querySelector('input[type=range]');
  const count = root.querySelector('.st-count');
  const label = root.querySelector('.st-label');
  const playButton = root.querySelector('[data-act=play]');
  const n = deck.frames.length;
  const cache = new Map();
  let current = 0, wanted = 0, drawing = false, timer = null;
  root.querySelector('.st-fallback').style.display = 'none';
  root.querySelector('.st-controls').style.display = 'flex';

  // One frame is drawn at a time; steps asked for meanwhile collapse into the last one.
  function draw() {
    if (drawing) return;
    drawing = true;
    const k = wanted;
    drawScantraceFrame(ctx, scantraceDeckFrame(deck, k, cache)).then(() => {
      current = k;
      root.dataset.shown = String(k);  // for tests and for anyone reading the page
      drawing = false;
      if (wanted !== k) draw();
    }, (err) => { drawing = false; label.textContent = 'cannot draw step ' + (k + 1) + ': ' + err; });
  }
  function show(k) {
    wanted = Math.max(0, Math.min(n - 1, k));
    slider.value = String(wanted);
    count.textContent = (wanted + 1) + ' / ' + n;
    label.textContent = deck.labels[wanted];
    draw();
  }
  function play(on) {
    if (timer !== null) clearInterval(timer);
    timer = null;
    if (on) {
      if (wanted >= n - 1) show(0);
      timer = setInterval(() => { if (wanted >= n - 1) play(false); else show(wanted + 1); }, 400);
    }
    playButton.textContent = timer === null ? '\u25B6 play' : '\u275A\u275A pause';
  }
  const actions = {
    first: () => show(0), back10: () => show(wanted - 10), prev: () => show(wanted - 1),
    next: () => show(wanted + 1), fwd10: () => show(wanted + 10), last: () => show(n - 1),
    play: () => play(timer === null),
  };
  for (const b of root.querySelectorAll('button[data-act]'))
    b.addEventListener('click', () => { actions[b.dataset.act](); root.focus(); });
  slider.addEventListener('input', () => show(parseInt(slider.value, 10)));
  // The keys act while the player has the focus (a click on it gives it), and only here: the
  // notebook's own shortcuts do not see them.
  root.addEventListener('keydown', (e) => {
    if (e.ctrlKey || e.altKey || e.metaKey) return;
    const keys = {
      ArrowRight: 'next', ' ': 'next', n: 'next', ArrowLeft: 'prev', p: 'prev',
      PageDown: 'fwd10', PageUp: 'back10', Home: 'first', End: 'last', a: 'play',
    };
    if (!(e.key in keys)) return;
    actions[keys[e.key]]();
    e.preventDefault();
    e.stopPropagation();
  });
  // For scripts of the page (and the tests): the deck, its frames as canvas JSON, the drawing.
  root.scantrace = {deck: deck, show: show, deckFrame: (k) => scantraceDeckFrame(deck, k, cache),
                    drawFrame: drawScantraceFrame};
  show(0);
}
