// The explorer's speed in headless Chromium (docs/performance.md, "In the browser"): how long it
// takes to open (navigation start to the first complete frame, by the page's clock: the module
// compiled and instantiated, the triangle filled and traced, the current step's frame drawn), and
// what a mouse move of a vertex drag costs (the page's handler around the module's fill, trace,
// plan and frame and their drawing; and the DevTools round trip of the synthesized move, which
// returns once the renderer has handled the event); and, in drags of their own, the move with its
// pixels rasterised (rasterHooks below). Medians; nothing is asserted.
//
//   node --experimental-websocket web/bench/explorer_drag.mjs EXPLORER.html [OPENS] [MOVES] [OTHER.html] [ROUNDS]
// With OTHER.html (another build's explorer, e.g. main's), the opens alternate between the two
// pages, each in a fresh browser, and so do the drags (ROUNDS rounds, four unless given, an even
// number: each page first in half of them); both medians printed.
import path from 'node:path';

import { launch, until } from '../tests/cdp.mjs';

const [explorer, opensArg, movesArg, other, roundsArg] = process.argv.slice(2);
const opens = Number(opensArg || 7), moves = Number(movesArg || 200);
const rounds = other ? Number(roundsArg || 4) : 1;
if (!(Number.isInteger(rounds) && rounds > 0 && (rounds === 1 || rounds % 2 === 0))) {
  console.error(`explorer_drag.mjs: ROUNDS must be an even number of rounds (each page first in half of them), got ${roundsArg}`);
  process.exit(2);
}
const median = (v) => [...v].sort((a, b) => a - b)[v.length >> 1];
const quartiles = (v) => { const s = [...v].sort((a, b) => a - b); return [s[s.length >> 2], s[(3 * s.length) >> 2]]; };

// Opens in fresh browsers (nothing compiled or cached from an earlier load), pages alternated.
async function openTimes(pages, n) {
  const times = pages.map(() => []), parts = pages.map(() => []);
  for (let i = 0; i < n; ++i)
    for (const [k, page] of pages.entries()) {
      const fresh = await launch();
      try {
        await fresh.page('Page.enable');
        await fresh.page('Page.navigate', { url: `file://${path.resolve(page)}#step=12` });
        await until('the page to start', () => fresh.evaluate("!!document.body && document.body.dataset.ready === '1'"), 60000);
        times[k].push(Number(await fresh.evaluate('document.body.dataset.readyMs')));
        parts[k].push(await fresh.evaluate("['script', 'inflated', 'loaded', 'ready'].map((k) => document.body.dataset[k + 'Ms']).join('/')"));
      } finally {
        await fresh.close();
      }
    }
  pages.forEach((page, k) => {
    console.log(`open ${page} in a fresh browser (navigation start to the first complete frame, ${n} loads): median ${median(times[k])} ms, all [${times[k].join(', ')}]`);
    console.log(`  script started / wasm inflated / module instantiated / first frame drawn, ms: ${parts[k].join(', ')}`);
  });
}
await openTimes(other ? [explorer, other] : [explorer], opens);

// Chromium records a canvas's drawing calls and rasterises them later, when the frame is
// presented (in software here, --disable-gpu): the handler's time leaves that out. A drag with
// `rastered` measures, on either page alike, from a capturing listener (which runs before the
// page's handler) to one that runs after it and reads a pixel of every canvas the page shows
// (the grid, the frame, and since the ninth round the fill's own canvas under the grid), which
// makes Skia rasterise everything drawn: the move's whole cost, the handler and its pixels.
const rasterHooks = `(() => {
  window.rasteredTimes = [];
  let t0 = 0;
  const shown = ['grid', 'frame', 'fill'].map((id) => document.getElementById(id)).filter((c) => c).map((c) => c.getContext('2d'));
  // From the pointer move (before the page's handler: a pointermove on the grid in newer
  // pages, a mousemove in older ones) to the compatibility mouse move after it, which follows both.
  window.addEventListener('pointermove', () => { t0 = performance.now(); }, true);
  window.addEventListener('mousemove', () => {
    for (const g of shown) g.getImageData(0, 0, 1, 1);
    window.rasteredTimes.push(performance.now() - t0);
  });
})()`;

// Vertex 2 of the course triangle dragged back and forth along a diagonal, step 13 shown, in a
// fresh browser: the handler's times of `moves` mouse moves (the first 30, V8 still compiling the
// module's functions, left out) and the DevTools round trips; with `rastered`, the times to the
// move's pixels rasterised instead (above).
async function dragTimes(page, moves, rastered = false) {
  const b = await launch();
  try {
    for (const d of ['Runtime', 'Page']) await b.page(`${d}.enable`);
    await b.page('Page.navigate', { url: `file://${path.resolve(page)}#step=12` });
    await until('the page to start', () => b.evaluate("!!document.body && document.body.dataset.ready === '1'"), 60000);
    // Step 13 shown: older pages read #step=12 as it, newer ones #step=13 (the step as shown).
    if ((await b.evaluate('explorer.state().step')) === 11) {
      await b.evaluate("location.hash = '#step=13'");
      await until('step 13', async () => (await b.evaluate('explorer.state().step')) === 12);
    }
    if (rastered) await b.evaluate(rasterHooks);
    const from = await b.evaluate('explorer.vertexOnScreen(2)');
    const mouse = (type, [x, y]) => b.page('Input.dispatchMouseEvent', { type, x, y, button: 'left', buttons: type === 'mouseReleased' ? 0 : 1, clickCount: 1 });
    const trip = [];
    await mouse('mousePressed', from);
    let at = from;
    for (let i = 1; i <= moves + 30; ++i) {
      // Back and forth over 54 pixels, never twice at the same place (steps of 0.1 radian): a
      // path that came back to the same 20 places (until the eighth round) drew from bitmaps
      // kept for text that a real drag, at 1/256 pixel, would never see again.
      const k = 27 * (1 - Math.cos(i * 0.1));
      at = [from[0] - k, from[1] - 0.6 * k];
      const t0 = performance.now();
      await mouse('mouseMoved', at);
      if (i > 30) trip.push(performance.now() - t0);
    }
    await mouse('mouseReleased', at);
    if (rastered) return { rastered: (await b.evaluate('window.rasteredTimes')).slice(30, moves + 30) };
    return { handler: (await b.evaluate('explorer.dragTimes()')).slice(30), trip,
      stages: (await b.evaluate('explorer.dragStages ? explorer.dragStages() : []')).slice(30) };
  } finally {
    await b.close();
  }
}

// With OTHER.html, the drags alternate between the two pages in ROUNDS rounds of MOVES / ROUNDS moves
// (the machine's load shifts over a run: each page gets its share of every period), each page
// first in half of them: whichever page went first in every round came out 1-2.5 ms slower a
// move, the same page listed first or second (docs/performance.md).
const pages = other ? [explorer, other] : [explorer];
const times = pages.map(() => ({ handler: [], trip: [], stages: [], rastered: [], rounds: [] }));
for (let r = 0; r < rounds; ++r)
  for (const [k, page] of (r % 2 ? [...pages.entries()].reverse() : [...pages.entries()])) {
    const t = await dragTimes(page, Math.ceil(moves / rounds));
    times[k].handler.push(...t.handler);
    times[k].trip.push(...t.trip);
    times[k].stages.push(...t.stages);
    const { rastered } = await dragTimes(page, Math.ceil(moves / rounds), true);
    times[k].rastered.push(...rastered);
    // Each round's own medians (handler / rasterised): the spread between rounds, which are
    // fresh browsers minutes apart, says how far one run's medians can be trusted.
    times[k].rounds.push(`${median(t.handler).toFixed(1)}/${median(rastered).toFixed(1)}`);
  }
pages.forEach((page, k) => {
  const { handler, trip, stages } = times[k];
  const [q1, q3] = quartiles(handler);
  console.log(`drag of vertex 2, step 13 shown, ${page} (${handler.length} moves${rounds > 1 ? ` in ${rounds} rounds alternated with the other page` : ''}): handler median ${median(handler).toFixed(1)} ms (quartiles ${q1.toFixed(1)}, ${q3.toFixed(1)}); DevTools round trip of a move median ${median(trip).toFixed(1)} ms`);
  if (stages.length) {
    // Each stage's own time: the difference of the ends, medians.
    const part = (a, b) => median(stages.map((x) => x[b] - (a ? x[a] : 0))).toFixed(1);
    console.log(`  stages, medians: traced fill ${part(null, 'trace')} ms, fill put on its canvas ${part('trace', 'fill')}, step frame composed ${part('fill', 'frame')}, drawn ${part('frame', 'drawn')}` +
      (stages[0].step !== undefined ? ` (the grid ${part('frame', 'grid')}, the frame ${part('grid', 'step')}, the tables ${part('step', 'drawn')})` : ''));
  }
  const { rastered } = times[k];
  const [r1, r3] = quartiles(rastered);
  console.log(`  the same drag with its pixels rasterised in the move (${rastered.length} moves, separate browsers): median ${median(rastered).toFixed(1)} ms (quartiles ${r1.toFixed(1)}, ${r3.toFixed(1)})`);
  if (rounds > 1) console.log(`  each round's medians, handler/rasterised ms: ${times[k].rounds.join(', ')}`);
});
