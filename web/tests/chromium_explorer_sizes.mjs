// The explorer as a class and a student see it, in headless Chromium at the sizes of a laptop on
// a projector (1366x768), a desktop (1920x1080) and a phone held upright (390x844, touch):
// - a screenshot at each size (and presenting at 1366x768, and the phone's whole page) kept in
//   WORK_DIR/screenshots/ (docs/web.md);
// - no control cut off (each inside the window's width) and no page scrolled sideways;
// - no text outside its box (each text's lines inside the element holding it);
// - the text readable: the frame's smallest text and the page's at least a 10-px font on the
//   phone and when presenting at 1366x768 (a frame's text measured from its glyphs' strokes);
// - a vertex dragged over 50 mouse moves at 1366x768, each move timed: printed, not asserted
//   (docs/performance.md, "The explorer at lecture sizes").
//
//   node --experimental-websocket --no-warnings chromium_explorer_sizes.mjs EXPLORER.html WORK_DIR
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';

import { checker, launch, until, watchProblems } from './cdp.mjs';
import { cutOff as cutOffIn, frameTextSize, kReadable, overflowing as overflowingIn, screenshot as screenshotIn, sizes, smallestPageFont } from './layout_checks.mjs';

const [explorer, work] = process.argv.slice(2);
const shots = path.join(work, 'screenshots');
fs.mkdirSync(shots, { recursive: true });
// A scanline step of the course triangle whose frame has both zoom insets.
const address = `file://${path.resolve(explorer)}#triangle=20,20;250,80;300,400&step=38`;
const b = await launch();
const problems = watchProblems(b);
const checks = checker();
const check = checks.check;

async function open(size) {
  await b.page('Emulation.setDeviceMetricsOverride', { width: size.width, height: size.height, deviceScaleFactor: 1, mobile: size.mobile });
  await b.page('Emulation.setTouchEmulationEnabled', size.mobile ? { enabled: true, maxTouchPoints: 5 } : { enabled: false });
  await b.page('Page.navigate', { url: 'about:blank' });
  await until('the blank page', () => b.evaluate("location.href === 'about:blank'"));
  await b.page('Page.navigate', { url: address });
  await until('the page', () => b.evaluate("!!document.body && document.body.dataset.ready === '1'"));
  await framed();
}

// The frame of the step shown, composed at its box's size (the page's rule: its CSS width in
// device pixels, between 320 and 1280, or 1920 presenting) and drawn.
async function framed() {
  await until('the frame at its box\'s size', () => b.evaluate(`(() => {
    const f = document.getElementById('frame'), most = document.body.classList.contains('presenting') ? 1920 : 1280;
    const want = Math.round(Math.max(320, Math.min(most, f.getBoundingClientRect().width)));
    return f.width === want && f.dataset.step === String(explorer.state().step);
  })()`));
}

const screenshot = (name, whole = false) => screenshotIn(b, shots, `explorer-${name}`, whole);
const cutOff = (width) => cutOffIn(b, width);
const overflowing = () => overflowingIn(b);

// The frame's smallest text as a font size in CSS pixels (the step's frame at the canvas's CSS
// scale), and the page's smallest font size among the texts seen.
async function smallestText() {
  const [css, f] = await b.evaluate(`(() => {
    const canvas = document.getElementById('frame');
    return [canvas.getBoundingClientRect().width / canvas.width,
      explorer.module().frames(null, { first: explorer.state().step, count: 1, ...explorer.frameSize() }).frames[0]];
  })()`);
  const t = frameTextSize(f, css), p = await smallestPageFont(b);
  return { frame: t.size, which: t.which, page: p.page, where: p.where };
}

const median = (v) => [...v].sort((a, c) => a - c)[v.length >> 1];
const quartiles = (v) => { const s = [...v].sort((a, c) => a - c); return [s[s.length >> 2], s[(3 * s.length) >> 2]]; };

// From the pointer move (before the page's handler) to the move's pixels rasterised (read back
// from each canvas after the handler: the compatibility mouse move follows it).
const rasterHooks = `(() => {
  window.rasteredTimes = [];
  let t0 = 0;
  const shown = ['grid', 'frame', 'fill'].map((id) => document.getElementById(id).getContext('2d'));
  window.addEventListener('pointermove', () => { t0 = performance.now(); }, true);
  window.addEventListener('mousemove', () => {
    for (const g of shown) g.getImageData(0, 0, 1, 1);
    window.rasteredTimes.push(performance.now() - t0);
  });
})()`;

try {
  for (const d of ['Runtime', 'Log', 'Network', 'Page']) await b.page(`${d}.enable`);

  for (const size of sizes) {
    await check(`at ${size.name}: a screenshot kept, no control cut off, no text outside its box`, async () => {
      await open(size);
      await screenshot(size.name);
      if (size.mobile) await screenshot(`${size.name}-page`, true);
      const cut = await cutOff(size.width);
      assert.deepStrictEqual(cut.out, [], `cut off at the window's edge (${cut.width} px)`);
      assert.ok(cut.scroll <= cut.width, `the page scrolls sideways: ${cut.scroll} px wide`);
      assert.deepStrictEqual(await overflowing(), []);
    });
  }

  await check('on the phone (390x844) the frame\'s text and the page\'s read as a font of 10 CSS px or more', async () => {
    await open(sizes[2]);
    const t = await smallestText();
    console.log(`390x844: the frame's smallest text ${t.frame.toFixed(1)} px ("${t.which}"), the page's ${t.page} px (${t.where})`);
    assert.ok(t.frame >= kReadable, `the frame's "${t.which}" reads as ${t.frame.toFixed(1)} px`);
    assert.ok(t.page >= kReadable, `the page's ${t.where} is ${t.page} px`);
  });

  await check('presenting at 1366x768: a screenshot kept, the frame\'s text a font of 10 CSS px or more', async () => {
    await open(sizes[0]);
    await b.evaluate("document.getElementById('present').click()");
    await until('presenting', () => b.evaluate("document.body.classList.contains('presenting')"));
    await framed();
    await screenshot('1366x768-presenting');
    const t = await smallestText();
    console.log(`1366x768 presenting: the frame's smallest text ${t.frame.toFixed(1)} px ("${t.which}")`);
    assert.ok(t.frame >= kReadable, `the frame's "${t.which}" reads as ${t.frame.toFixed(1)} px`);
    assert.deepStrictEqual((await cutOff(1366)).out, []);
    await b.evaluate("document.getElementById('present').click()");
  });

  await check('a vertex dragged at 1366x768: 50 mouse moves timed (30 before them not counted)', async () => {
    await open(sizes[0]);
    await b.evaluate(rasterHooks);
    const from = await b.evaluate('explorer.vertexOnScreen(2)');
    const mouse = (type, [x, y]) => b.page('Input.dispatchMouseEvent', { type, x, y, button: 'left', buttons: type === 'mouseReleased' ? 0 : 1, clickCount: 1 });
    await mouse('mousePressed', from);
    // Back and forth over 54 pixels, never twice at the same place, as web/bench/explorer_drag.mjs.
    for (let i = 1; i <= 80; ++i) await mouse('mouseMoved', [from[0] - 27 * (1 - Math.cos(0.1 * i)), from[1] - 20 * (1 - Math.cos(0.1 * i))]);
    await mouse('mouseReleased', from);
    const handler = (await b.evaluate('explorer.dragTimes()')).slice(30);
    const rastered = (await b.evaluate('window.rasteredTimes')).slice(-handler.length);
    assert.equal(handler.length, 50);
    const say = (v) => `${median(v).toFixed(1)} ms (quartiles ${quartiles(v).map((t) => t.toFixed(1)).join(', ')})`;
    console.log(`a drag's move at 1366x768, median of 50: the handler ${say(handler)}; rasterised ${say(rastered)}`);
  });

  await check('no console error, no exception, no network request', async () => {
    assert.deepStrictEqual(problems, []);
  });
} finally {
  await b.page('Emulation.setTouchEmulationEnabled', { enabled: false }).catch(() => {});
  await b.close();
}
console.log(`${checks.passed} checks passed${process.exitCode ? ', some FAILED' : ''}; screenshots in ${shots}`);
