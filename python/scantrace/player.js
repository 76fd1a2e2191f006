// The inline trace player of the scantrace Python package (Trace._repr_html_, _player.py): a
// <canvas> that draws one frame of a deck (python/src/player_deck.hpp) at a time through the
// canvas backend's drawScantraceFrame, on the player core every page shares (keys, buttons,
// slider, play and its speed, g, the help: web/player/, with its Hershey layout). Both are
// inserted before this script (_scantrace.frame_canvas_script(), player_core_script()). Nothing
// is loaded from anywhere: the deck is in the page.
/* global drawScantraceFrame, scantraceHersheyStrokes, createStepper, bindPlayer, playerKeys, SCANTRACE_KEYS */

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
  const label = root.querySelector('.st-label');
  const n = deck.frames.length;
  const cache = new Map();
  let wanted = 0, drawing = false;
  root.querySelector('.st-fallback').style.display = 'none';
  root.querySelector('.st-controls').style.display = 'flex';

  // One frame is drawn at a time; steps asked for meanwhile collapse into the last one.
  function draw() {
    if (drawing) return;
    drawing = true;
    const k = wanted;
    drawScantraceFrame(ctx, scantraceDeckFrame(deck, k, cache)).then(() => {
      root.dataset.shown = String(k);  // for tests and for anyone reading the page
      drawing = false;
      if (wanted !== k) draw();
    }, (err) => { drawing = false; label.textContent = 'cannot draw step ' + (k + 1) + ': ' + err; });
  }
  const s = createStepper({
    count: n, rows: deck.rows, speed: 2.5,
    say: (text) => { label.textContent = text || deck.labels[wanted]; },
    show: (k) => { wanted = k; label.textContent = deck.labels[k]; draw(); },
  });
  // The keys act while the player has the focus (a click on it gives it), and only here: the
  // notebook's own shortcuts do not see them.
  bindPlayer(s, {
    scope: root, keys: playerKeys(SCANTRACE_KEYS, 'python'), first: 1,
    slider: root.querySelector('input[type=range]'), counter: root.querySelector('.st-count'),
    counterText: () => (s.index + 1) + ' / ' + n, playButton: root.querySelector('[data-act=play]'),
    speed: root.querySelector('select'), help: root.querySelector('.st-help'),
  });
  root.addEventListener('click', (e) => { if (e.target.tagName !== 'SELECT') root.focus(); });
  // For scripts of the page (and the tests): the deck, its frames as canvas JSON, the drawing.
  root.scantrace = {deck: deck, show: s.go, deckFrame: (k) => scantraceDeckFrame(deck, k, cache),
                    drawFrame: drawScantraceFrame};
  s.go(0);
}
