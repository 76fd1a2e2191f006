// The trace page (`explain`/`replay -o OUT.html`) as a class and a student see it, in headless
// Chromium at the sizes of a laptop on a projector (1366x768), a desktop (1920x1080) and a phone
// held upright (390x844, touch, mobile):
// - a screenshot of the course triangle's page at each size (and of the phone's whole page)
//   kept in WORK_DIR/screenshots/ (docs/web.md);
// - no control cut off (each inside the screen's width, or inside a box that scrolls sideways
//   that is), no page scrolled sideways, no text outside its box;
// - on the phone, the frame's smallest text (measured on the full module's frame of the step
//   shown, at the canvas's CSS scale) and the page's at least a 10-px font;
// - every control and the canvas named in the accessibility tree, Tab reaching the canvas;
// - after a step, the live region says the step's sentence: a small triangle one row a step,
//   step 19 is row 15 (1 title + 1 set-up + 3 edge-table entries, then rows 2.. from step 6,
//   counted by hand).
//
//   node --experimental-websocket --no-warnings chromium_trace_page_sizes.mjs SCANTRACE WORK_DIR WEB_DIR
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import zlib from 'node:zlib';

import { checker, launch, until, watchProblems } from './cdp.mjs';
import { cutOff, frameTextSize, kReadable, overflowing, screenshot, sizes, smallestPageFont, unnamedControls } from './layout_checks.mjs';

const [scantraceArg, work, webDir] = process.argv.slice(2);
const shots = path.join(work, 'screenshots');
fs.mkdirSync(shots, { recursive: true });
const native = (args) => {
  const r = spawnSync(path.resolve(scantraceArg), ['-q', ...args], { encoding: 'utf8', cwd: work });
  if (r.status !== 0) throw new Error(`scantrace ${args.join(' ')}: exit ${r.status}: ${r.stderr}`);
};
native(['explain', '--triangle', '20,20 250,80 300,400', '-o', 'course_triangle.html']);
native(['trace', '--triangle', '2.3,1.2 29,9.5 8,27.6', '--size', '32x30', '-o', 't.jsonl']);
native(['replay', 't.jsonl', '-o', 't.html', '--video-size', '640x360', '--rows-per-step', '1']);
const { load } = await import(pathToFileURL(path.join(webDir, 'scantrace.mjs')));
const full = await load();

// A scanline step of the course triangle's 47, its frame with a zoom inset.
const courseStep = 30;

const b = await launch();
const problems = watchProblems(b);
const checks = checker();
const check = checks.check;
const key = async (k, code) => {
  await b.page('Input.dispatchKeyEvent', { type: 'rawKeyDown', key: k, code: k, windowsVirtualKeyCode: code });
  await b.page('Input.dispatchKeyEvent', { type: 'keyUp', key: k, code: k });
};
const drawn = (step) => until(`step ${step} drawn`, () => b.evaluate(`document.getElementById('frame').dataset.step === '${step - 1}'`));

async function open(size, file, step) {
  await b.page('Emulation.setDeviceMetricsOverride', { width: size.width, height: size.height, deviceScaleFactor: 1, mobile: size.mobile });
  await b.page('Emulation.setTouchEmulationEnabled', size.mobile ? { enabled: true, maxTouchPoints: 5 } : { enabled: false });
  await b.page('Page.navigate', { url: 'about:blank' });
  await until('the blank page', () => b.evaluate("location.href === 'about:blank'"));
  await b.page('Page.navigate', { url: `file://${path.join(work, file)}#step=${step}` });
  await until('the page', () => b.evaluate("!!document.body && document.body.dataset.ready === '1'"));
  await drawn(step);
}

// The full module's frame of the open page's step (from 1), composed from what the page holds.
function fullFrame(file, step) {
  const { cfg, trace } = JSON.parse(/const page = (\{.*\});$/m.exec(fs.readFileSync(path.join(work, file), 'utf8'))[1]);
  const text = zlib.gunzipSync(Buffer.from(trace, 'base64')).toString('utf8');
  const options = { width: cfg.width, height: cfg.height, rows_per_step: cfg.rows_per_step, mode: cfg.mode, source: cfg.source };
  return full.frames(text, { ...options, first: cfg.first + step - 1, count: 1 }).frames[0];
}

try {
  for (const d of ['Runtime', 'Log', 'Network', 'Page']) await b.page(`${d}.enable`);

  for (const size of sizes) {
    await check(`at ${size.name}: a screenshot kept, no control cut off, no sideways scroll, no text outside its box, every control named`, async () => {
      await open(size, 'course_triangle.html', courseStep);
      await screenshot(b, shots, `trace-page-${size.name}`);
      if (size.mobile) await screenshot(b, shots, `trace-page-${size.name}-page`, true);
      const cut = await cutOff(b, size.width);
      assert.deepStrictEqual(cut.out, [], `cut off at the window's edge (${cut.width} px)`);
      assert.ok(cut.scroll <= cut.width, `the page scrolls sideways: ${cut.scroll} px wide`);
      assert.deepStrictEqual(await overflowing(b), []);
      assert.deepStrictEqual(await unnamedControls(b), [], 'controls without a name');
    });
  }

  await check('on the phone (390x844) the frame\'s text and the page\'s read as a font of 10 CSS px or more', async () => {
    await open(sizes[2], 'course_triangle.html', courseStep);
    const css = await b.evaluate("(() => { const c = document.getElementById('frame'); return c.getBoundingClientRect().width; })()");
    const f = fullFrame('course_triangle.html', courseStep);
    const t = frameTextSize(f, css / f.w);
    const p = await smallestPageFont(b);
    console.log(`390x844: the frame ${Math.round(css)} CSS px wide, its smallest text ${t.size.toFixed(1)} px ("${t.which}"), the page's ${p.page} px (${p.where})`);
    assert.ok(t.size >= kReadable, `the frame's "${t.which}" reads as ${t.size.toFixed(1)} px`);
    assert.ok(p.page >= kReadable, `the page's ${p.where} is ${p.page} px`);
  });

  await check('the canvas named, an image, reached by Tab', async () => {
    const canvas = await b.evaluate("(() => { const c = document.getElementById('frame'); return [c.getAttribute('role'), (c.getAttribute('aria-label') || '').length > 10]; })()");
    assert.deepStrictEqual(canvas, ['img', true]);
    await b.evaluate('document.activeElement && document.activeElement.blur()');
    const reached = new Set();
    for (let i = 0; i < 30 && !reached.has('frame'); ++i) {
      await key('Tab', 9);
      reached.add(await b.evaluate('document.activeElement.id'));
    }
    assert.ok(reached.has('frame'), `Tab reached ${[...reached]}`);
  });

  for (const size of [sizes[0], sizes[2]]) {
    await check(`at ${size.name}: after a step, the live region says the step's sentence (step 19: row 15)`, async () => {
      await open(size, 't.html', 18);
      await b.evaluate("document.getElementById('frame').focus()");
      await key('ArrowRight', 39);
      await drawn(19);
      const live = await b.evaluate("[...document.querySelectorAll('[aria-live=polite]')].map((e) => e.textContent)");
      assert.ok(live.includes('step 19 / 33: rows 15..15 of triangle 0'), JSON.stringify(live));
    });
  }

  await check('no console error, no exception, no network request', () => assert.deepStrictEqual(problems, []));
} finally {
  await b.page('Emulation.setTouchEmulationEnabled', { enabled: false }).catch(() => {});
  await b.close();
}
console.log(`${checks.passed} checks passed${process.exitCode ? ', some FAILED' : ''}; screenshots in ${shots}`);
