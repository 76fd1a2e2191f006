// How fast a trace page opens and steps in headless Chromium (docs/performance.md): two pages of
// the same trace, e.g. one written by an older build and one by this one, alternated, each load
// in a fresh browser at 1280×800. For each: the bytes, the page's own mark of a working page
// (body.dataset.readyMs: milliseconds from navigation start) and the time from a → key to the
// canvas holding the next step's frame (canvas.dataset.step), over steps 1..N; medians.
//
//   node --experimental-websocket trace_page.mjs OLD.html NEW.html [ROUNDS=5] [STEPS=20]
import fs from 'node:fs';
import path from 'node:path';

import { launch, until } from '../tests/cdp.mjs';

const [oldPage, newPage, roundsArg, stepsArg] = process.argv.slice(2);
if (!oldPage || !newPage) {
  console.error('usage: node --experimental-websocket trace_page.mjs OLD.html NEW.html [ROUNDS] [STEPS]');
  process.exit(2);
}
const rounds = Number(roundsArg || 5), steps = Number(stepsArg || 20);
const median = (a) => [...a].sort((x, y) => x - y)[a.length >> 1];

async function measure(file) {
  const b = await launch();
  try {
    await b.page('Page.enable');
    await b.page('Emulation.setDeviceMetricsOverride', { width: 1280, height: 800, deviceScaleFactor: 1, mobile: false });
    await b.page('Page.navigate', { url: `file://${path.resolve(file)}` });
    await until('the page to start', () => b.evaluate("!!document.body && document.body.dataset.ready === '1'"), 60000);
    await until('step 1 drawn', async () => (await b.evaluate("document.getElementById('frame').dataset.step")) === '0', 60000);
    const ready = Number(await b.evaluate('document.body.dataset.readyMs'));
    const times = [];
    for (let k = 1; k <= steps; ++k) {
      const t0 = performance.now();
      await b.page('Input.dispatchKeyEvent', { type: 'rawKeyDown', key: 'ArrowRight', code: 'ArrowRight', windowsVirtualKeyCode: 39 });
      await b.page('Input.dispatchKeyEvent', { type: 'keyUp', key: 'ArrowRight', code: 'ArrowRight' });
      await until(`step ${k + 1} drawn`, async () => (await b.evaluate("document.getElementById('frame').dataset.step")) === String(k), 60000);
      times.push(performance.now() - t0);
    }
    return { ready, step: median(times) };
  } finally {
    await b.close();
  }
}

const results = { [oldPage]: [], [newPage]: [] };
for (let r = 0; r < rounds; ++r)
  for (const file of [oldPage, newPage]) results[file].push(await measure(file));
for (const file of [oldPage, newPage]) {
  const rs = results[file];
  console.log(`${file}: ${fs.statSync(file).size} bytes; ready ${median(rs.map((x) => x.ready))} ms ` +
              `(${rs.map((x) => x.ready).join(' ')}); a step ${median(rs.map((x) => x.step)).toFixed(0)} ms ` +
              `(${rs.map((x) => x.step.toFixed(0)).join(' ')})`);
}
