// The explorer in headless Chromium (issue 33; docs/web.md), opened from file:// with real input
// events over the DevTools protocol, checked against the native command:
// - the address restores the state (shading, step);
// - dragging a vertex changes the trace shown into the native `trace` of the new triangle;
// - `scantrace step`'s keys step; a click on a pixel shows that pixel's `why --json`;
// - the page's fill pixels equal the native render; a PNG given for an open scene is diffed as
//   `diff --json` diffs it, and so is a .npy; a malformed scene, a PNG declaring 100000 x 100000
//   pixels and a .npy holding a pickle show `scantrace diff`'s line and the page keeps working;
// - no console error, no exception, no network request.
//
//   node --experimental-websocket chromium_explorer.mjs EXPLORER.html SCANTRACE WORK_DIR
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';

import { checker, launch, until, watchProblems } from './cdp.mjs';
import { decodePng, encodePng, pngChunk, pngSignature } from './png.mjs';

const [explorer, scantraceArg, work] = process.argv.slice(2);
const scantrace = path.resolve(scantraceArg);
fs.mkdirSync(work, { recursive: true });
const native = (args, ok = [0]) => {
  const r = spawnSync(scantrace, ['-q', ...args], { encoding: 'utf8', cwd: work, maxBuffer: 1 << 28 });
  if (!ok.includes(r.status)) throw new Error(`scantrace ${args.join(' ')}: exit ${r.status}: ${r.stderr}`);
  return r;
};
const jsonl = (text) => text.split('\n').filter((l) => l).map((l) => JSON.parse(l));

const b = await launch();
const problems = watchProblems(b);
const checks = checker();
const check = checks.check;
const text = (id) => b.evaluate(`document.getElementById(${JSON.stringify(id)}).textContent`);
const mouse = async (type, [x, y]) => b.page('Input.dispatchMouseEvent', { type, x, y, button: 'left', buttons: type === 'mouseReleased' ? 0 : 1, clickCount: 1 });
const key = async (k, code) => {
  await b.page('Input.dispatchKeyEvent', { type: 'rawKeyDown', key: k, code, windowsVirtualKeyCode: { ArrowRight: 39, ArrowLeft: 37, PageDown: 34, PageUp: 33, Home: 36, End: 35 }[k] });
  await b.page('Input.dispatchKeyEvent', { type: 'keyUp', key: k, code });
};
const stepShown = async () => Number((await text('step-no')).match(/step (\d+)/)[1]) - 1;

// The channel values in which the frame canvas differs from the current step's frame of the kept
// trace drawn whole on a fresh canvas at the size the page composes (-1: the sizes differ).
const staleValues = () => b.evaluate(`(() => {
  const st = explorer.module();
  const draw = new Function(st.canvasScript() + '; return drawScantraceFrame;')();
  const f = st.frames(null, { first: explorer.state().step, count: 1, source: 'the explorer\u2019s triangle', blocks: 'rgba', ...explorer.frameSize() }).frames[0];
  const c = document.createElement('canvas');
  c.width = f.w;
  c.height = f.h;
  draw(c.getContext('2d'), f);
  const want = c.getContext('2d').getImageData(0, 0, f.w, f.h).data, got = explorer.framePixels();
  let n = got.length === want.length ? 0 : -1;
  for (let i = 0; n >= 0 && i < want.length; ++i) if (want[i] !== got[i]) ++n;
  return n;
})()`);

try {
  for (const d of ['Runtime', 'Log', 'Network', 'Page', 'DOM']) await b.page(`${d}.enable`);
  const url = `file://${path.resolve(explorer)}#triangle=20,20;250,80;300,400&shading=flat&step=12`;
  const t0 = Date.now();
  await b.page('Page.navigate', { url });
  await until('the page to start', () => b.evaluate("!!document.body && document.body.dataset.ready === '1'"));
  console.log(`explorer ready ${Date.now() - t0} ms after navigating (${await b.evaluate("document.body.dataset.readyMs")} ms by the page's clock)`);

  await check('the address restores the state', async () => {
    assert.equal(await b.evaluate("document.getElementById('shading').value"), 'flat');
    // #step=12 is the step shown as 'step 12', as on the trace page (web/player/player.js).
    assert.match(await text('step-no'), /^step 12 \//);
    assert.equal(await stepShown(), 11);
    assert.deepStrictEqual((await b.evaluate('explorer.state()')).triangle, [[20, 20], [250, 80], [300, 400]]);
  });

  await check('the page title says what it shows, and follows the step', async () => {
    const n = Number((await text('step-no')).match(/\/ (\d+)/)[1]);
    assert.equal(await b.evaluate('document.title'), `scantrace explorer: triangle (20,20) (250,80) (300,400), step 12 of ${n}`);
    await key('ArrowRight', 'ArrowRight');
    assert.equal(await b.evaluate('document.title'), `scantrace explorer: triangle (20,20) (250,80) (300,400), step 13 of ${n}`);
    await key('ArrowLeft', 'ArrowLeft');
  });

  await check('the trace shown is the native trace', async () => {
    native(['trace', '--triangle', '20,20 250,80 300,400', '--shading', 'flat', '-o', 'before.jsonl']);
    assert.deepStrictEqual(jsonl(await b.evaluate('explorer.traceText()')), jsonl(fs.readFileSync(path.join(work, 'before.jsonl'), 'utf8')));
  });

  await check('dragging a vertex re-traces as the native trace of the new triangle', async () => {
    const from = await b.evaluate('explorer.vertexOnScreen(2)');
    const to = [from[0] - 83.3, from[1] - 121.7];
    await mouse('mousePressed', from);
    for (let i = 1; i <= 5; ++i) await mouse('mouseMoved', [from[0] + (to[0] - from[0]) * i / 5, from[1] + (to[1] - from[1]) * i / 5]);
    // Before the release (the moves keep the trace in the module without its JSON Lines): the
    // tables show the native trace's edge table and current row of the triangle as it is now.
    const moving = (await b.evaluate('explorer.state()')).triangle;
    native(['trace', '--triangle', moving.map((v) => v.join(',')).join(' '), '--shading', 'flat', '-o', 'moving.jsonl']);
    const movingTrace = jsonl(fs.readFileSync(path.join(work, 'moving.jsonl'), 'utf8'));
    const edgeTable = await text('edge-table');
    for (const e of movingTrace.find((ev) => ev.type === 'edge_table').edges)
      assert.ok(edgeTable.includes(`edge ${e.edge}: (${e.from}) -> (${e.to})  rows ${e.first_row}..${e.last_row}  x@ymin ${e.x_at_y_min}  dx/dy ${e.dx_dy}`), edgeTable);
    const active = await text('active');
    const y = Number(active.match(/^y = (-?\d+)/)[1]);
    const row = movingTrace.find((ev) => ev.type === 'scanline' && ev.y === y);
    assert.ok(row, `row ${y} is in the native trace`);
    for (const a of row.active_edges) assert.ok(active.includes(`edge ${a.edge}  x = ${a.x}`), active);
    // The canvas holds the step's frame of the triangle as it is now, drawn whole.
    const stale = await staleValues();
    assert.equal(stale, 0, `the frame shown while dragging differs from the frame drawn whole in ${stale} channel values`);
    // And the fill's canvas the whole image of the triangle as it is now (the vertex went up by
    // 120 pixels: the rows it left are background again).
    const staleFill = await b.evaluate(`(() => {
      const want = explorer.module().lastTraceImage.rgba, got = explorer.fillPixels();
      let n = got.length === want.length ? 0 : -1;
      for (let i = 0; n >= 0 && i < want.length; ++i) if (want[i] !== got[i]) ++n;
      return n;
    })()`);
    assert.equal(staleFill, 0, `the fill's canvas while dragging differs from the traced fill's image in ${staleFill} channel values`);
    await mouse('mouseReleased', to);
    const moves = await b.evaluate('explorer.dragTimes()');
    console.log(`a drag's moves took ${moves.map((t) => t.toFixed(1)).join(', ')} ms (fill, trace, plan, the step's frame drawn; web/bench/explorer_drag.mjs takes medians)`);
    const tri = (await b.evaluate('explorer.state()')).triangle;
    assert.notDeepStrictEqual(tri[2], [300, 400]);
    // Snapped to the 2^-8 grid.
    for (const v of tri[2]) assert.equal(v * 256, Math.round(v * 256));
    native(['trace', '--triangle', tri.map((v) => v.join(',')).join(' '), '--shading', 'flat', '-o', 'after.jsonl']);
    const shown = jsonl(await b.evaluate('explorer.traceText()'));
    assert.deepStrictEqual(shown, jsonl(fs.readFileSync(path.join(work, 'after.jsonl'), 'utf8')));
    assert.notDeepStrictEqual(shown, jsonl(fs.readFileSync(path.join(work, 'before.jsonl'), 'utf8')));
    assert.ok((await b.evaluate('location.hash')).includes(`triangle=${tri.map((v) => v.join(',')).join(';')}`));
  });

  await check("scantrace step's keys step", async () => {
    await key('Home', 'Home');
    assert.equal(await stepShown(), 0);
    await key('ArrowRight', 'ArrowRight');
    await key('ArrowRight', 'ArrowRight');
    assert.equal(await stepShown(), 2);
    await key('PageDown', 'PageDown');
    assert.equal(await stepShown(), 12);
    await key('ArrowLeft', 'ArrowLeft');
    assert.equal(await stepShown(), 11);
    await key('End', 'End');
    const n = Number((await text('step-no')).match(/\/ (\d+)/)[1]);
    assert.equal(await stepShown(), n - 1);
    await key('PageUp', 'PageUp');
    assert.equal(await stepShown(), n - 11);
    await until('the frame of the step drawn', async () => (await b.evaluate("document.getElementById('frame').dataset.step")) === String(n - 11));
  });

  const click = async (selector) => {
    const at = await b.evaluate(`(() => { const el = document.querySelector(${JSON.stringify(selector)}); el.scrollIntoView({ block: 'nearest' }); const r = el.getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2]; })()`);
    await mouse('mousePressed', at);
    await mouse('mouseReleased', at);
  };
  const typeKey = async (k) => {
    await b.page('Input.dispatchKeyEvent', { type: 'keyDown', key: k, text: k.length === 1 ? k : k === 'Enter' ? '\r' : undefined, windowsVirtualKeyCode: k === 'Enter' ? 13 : k === 'Escape' ? 27 : k.length === 1 ? k.toUpperCase().charCodeAt(0) : 0 });
    await b.page('Input.dispatchKeyEvent', { type: 'keyUp', key: k });
  };

  await check('the keys step after a dropdown is used, and the arrow keys never change a dropdown', async () => {
    await key('Home', 'Home');
    // The shading dropdown chosen by the mouse's click and the keyboard (focus, then a change).
    await click('#shading');
    await b.evaluate("(() => { const el = document.getElementById('shading'); el.focus(); el.value = 'gouraud'; el.dispatchEvent(new Event('change')); })()");
    await key('ArrowRight', 'ArrowRight');
    assert.equal(await stepShown(), 1, 'ArrowRight after the dropdown did not step');
    // A dropdown that has the focus: ↓ ↑ leave its value, → ← step.
    await b.evaluate("document.getElementById('shading').focus()");
    for (const [k, vk] of [['ArrowDown', 40], ['ArrowUp', 38], ['ArrowDown', 40]]) {
      await b.page('Input.dispatchKeyEvent', { type: 'rawKeyDown', key: k, code: k, windowsVirtualKeyCode: vk });
      await b.page('Input.dispatchKeyEvent', { type: 'keyUp', key: k, code: k });
    }
    assert.equal(await b.evaluate("document.getElementById('shading').value"), 'gouraud');
    await b.evaluate("document.getElementById('shading').focus()");
    await key('ArrowRight', 'ArrowRight');
    assert.equal(await stepShown(), 2);
    assert.equal(await b.evaluate("document.getElementById('shading').value"), 'gouraud');
    // Back to flat, as the next checks expect.
    await b.evaluate("(() => { const el = document.getElementById('shading'); el.value = 'flat'; el.dispatchEvent(new Event('change')); })()");
  });

  await check('the player: step list, play at a speed, one-row and ten-row steps, g, ? and a link to the step', async () => {
    const n = Number((await text('step-no')).match(/\/ (\d+)/)[1]);
    // The list: one item a step, titled as the step line says, the current one marked.
    const items = await b.evaluate("[...document.querySelectorAll('#step-list li')].map((li) => [li.textContent, li.hasAttribute('aria-current')])");
    assert.equal(items.length, n);
    // Every step's title its own (the edge table's entries numbered).
    assert.equal(new Set(items.map((it) => it[0])).size, n, items.map((it) => it[0]).join(' | '));
    assert.deepStrictEqual(items.map((it, i) => [i, it[1]]).filter((it) => it[1]).map((it) => it[0]), [await stepShown()]);
    await click('#step-list li:nth-child(7)');
    assert.equal(await stepShown(), 6);
    assert.equal(await text('step-kind'), items[6][0]);
    assert.equal(await b.evaluate("document.querySelector('#step-list li[aria-current]').textContent"), items[6][0]);
    // Play at 8 steps a second: on by a few steps in a second, then paused, still.
    await b.evaluate("(() => { const el = document.getElementById('speed'); el.value = '8'; el.dispatchEvent(new Event('change')); })()");
    await click('#play');
    await new Promise((r) => setTimeout(r, 1000));
    await click('#play');
    const played = await stepShown();
    assert.ok(played >= 6 + 3, `at 8 steps a second, a second went from step 7 to step ${played + 1}`);
    await new Promise((r) => setTimeout(r, 400));
    assert.equal(await stepShown(), played, 'paused, yet stepping');
    assert.equal(await text('play'), 'play');
    // Rows a step: one, then ten (the composer's steps; rows where an edge enters or leaves keep a
    // step of their own), then the composer's choice again.
    const rowsOf = () => b.evaluate("(() => { const s = explorer.state(); return explorer.module().frames(null, { count: 0, rows_per_step: s.rows_per_step }).steps.filter((p) => p.kind === 'scanlines').map((p) => p.last_row - p.first_row + 1); })()");
    const auto = await rowsOf();
    for (const [rows, max] of [['1', 1], ['10', 10]]) {
      await b.evaluate(`(() => { const el = document.getElementById('rows'); el.value = '${rows}'; el.dispatchEvent(new Event('change')); })()`);
      const got = await rowsOf();
      assert.equal(Math.max(...got), max, `rows a step ${rows}: ${got}`);
      const listed = await b.evaluate("document.querySelectorAll('#step-list li').length");
      assert.equal(listed, Number((await text('step-no')).match(/\/ (\d+)/)[1]));
      assert.ok((await b.evaluate('location.hash')).includes(`rows=${rows}`));
    }
    assert.ok(Math.max(...auto) > 1 && Math.max(...auto) < 10, `the composer's own choice: ${Math.max(...auto)} rows`);
    await b.evaluate("(() => { const el = document.getElementById('rows'); el.value = '0'; el.dispatchEvent(new Event('change')); })()");
    // g, a row, Enter: the step of that row.
    await typeKey('g');
    assert.equal(await b.evaluate("document.activeElement.id"), 'goto-row');
    for (const c of '200') await typeKey(c);
    await typeKey('Enter');
    const step = await b.evaluate('(() => { const s = explorer.state(); return explorer.module().frames(null, { count: 0 }).steps[s.step]; })()');
    assert.ok(step.kind === 'scanlines' && step.first_row <= 200 && 200 <= step.last_row, JSON.stringify(step));
    assert.equal(await b.evaluate('document.activeElement === document.body'), true);
    // ? shows the keys, Esc hides them.
    await typeKey('?');
    assert.equal(await b.evaluate("document.getElementById('help').hidden"), false);
    assert.ok((await text('help')).includes('previous step'));
    await typeKey('Escape');
    assert.equal(await b.evaluate("document.getElementById('help').hidden"), true);
    // The link: the address of the step shown, its number as the page shows it.
    await click('#copy-link');
    await until('the link said', async () => (await text('link-status')).includes('file://'));
    const href = await b.evaluate('location.href');
    assert.ok((await text('link-status')).endsWith(href), await text('link-status'));
    assert.ok(href.includes(`step=${(await stepShown()) + 1}`), href);
    // The step the next checks expect (as the keys' check left it).
    await key('End', 'End');
    await key('PageUp', 'PageUp');
  });

  await check("every key of the key table's explorer actions does its action, and ? lists exactly those actions", async () => {
    // The explorer's actions, written out here, so an action dropped from keys.json fails.
    const expected = ['next', 'previous', 'forward10', 'back10', 'first', 'last', 'go_to_row', 'play', 'copy_link', 'present', 'help', 'close'];
    const table = JSON.parse(fs.readFileSync(new URL('../player/keys.json', import.meta.url), 'utf8'));
    const actions = table.actions.filter((a) => a.in.includes('explorer'));
    assert.deepStrictEqual(actions.map((a) => a.action).sort(), [...expected].sort());
    // The help: one row per action but Esc's close (the help line of ? and f say it), in the
    // table's order, with its label and help line.
    await click('#help-button');
    const rows = await b.evaluate("[...document.querySelectorAll('#help tr')].map((tr) => [...tr.cells].map((td) => td.textContent))");
    await click('#help-button');
    assert.deepStrictEqual(rows, actions.filter((a) => a.action !== 'close').map((a) => [a.label, a.help]));
    // The player's buttons name their keys, from the table too.
    const byName = Object.fromEntries(actions.map((a) => [a.action, a]));
    const buttons = [['prev', 'previous'], ['play', 'play'], ['next', 'next'], ['copy-link', 'copy_link'], ['present', 'present'], ['help-button', 'help']];
    const titles = await b.evaluate(`${JSON.stringify(buttons.map((x) => x[0]))}.map((id) => document.getElementById(id).title)`);
    assert.deepStrictEqual(titles, buttons.map(([, a]) => `${byName[a].help} (${byName[a].label})`));
    const n = Number((await text('step-no')).match(/\/ (\d+)/)[1]);
    const clamp = (k) => Math.max(0, Math.min(n - 1, k));
    // Each step action's step from step 12 (index 11), and each other action's effect seen.
    const moves = { next: (k) => k + 1, previous: (k) => k - 1, forward10: (k) => k + 10, back10: (k) => k - 10, first: () => 0, last: () => n - 1 };
    const state = () => b.evaluate(`(() => { const $ = (id) => document.getElementById(id); return { play: $('play').textContent, help: !$('help').hidden, goto: !$('goto').hidden && document.activeElement.id === 'goto-row', presenting: document.body.classList.contains('presenting'), link: $('link-status').textContent }; })()`);
    const press = async (k) => {
      await b.evaluate('document.activeElement && document.activeElement.blur()');
      if (k.length === 1 || k === 'Escape') await typeKey(k);
      else await key(k, k);
    };
    const done = [];
    for (const a of actions)
      for (const k of a.keys) {
        const what = `${a.action} by ${JSON.stringify(k)}`;
        if (moves[a.action]) {
          await click('#step-list li:nth-child(12)');
          await press(k);
          assert.equal(await stepShown(), clamp(moves[a.action](11)), what);
        } else if (a.action === 'play') {
          await press(k);
          assert.equal((await state()).play, 'pause', what);
          await press(k);
          assert.equal((await state()).play, 'play', what);
        } else if (a.action === 'go_to_row') {
          await press(k);
          assert.equal((await state()).goto, true, what);
          await typeKey('Escape');
          assert.equal((await state()).goto, false, what);
        } else if (a.action === 'copy_link') {
          await b.evaluate("document.getElementById('link-status').textContent = ''");
          await press(k);
          await until(what, async () => (await state()).link.includes('file://'));
        } else if (a.action === 'help' || a.action === 'present') {
          const on = a.action === 'help' ? 'help' : 'presenting';
          await press(k);
          await until(what, async () => (await state())[on]);
          // Esc (the close action, checked here) closes the keys and leaves the presentation.
          await press('Escape');
          await until(`${what}, then Esc`, async () => !(await state())[on]);
        } else if (a.action !== 'close') assert.fail(`no check of ${what}`);
        done.push(a.action);
      }
    assert.deepStrictEqual([...new Set(done)].sort(), [...expected].sort());
    // The step the next checks expect (as the keys' check left it).
    await key('End', 'End');
    await key('PageUp', 'PageUp');
  });

  await check('presentation (f) at 1366x768: the frame alone, as large as the screen, composed at that size; the keys step; Esc leaves', async () => {
    // The height of the smallest text of the frame shown, in its pixels: of each text op the
    // tallest glyph (its strokes' extent), the least of those.
    const smallestText = () => b.evaluate(`(() => {
      const f = explorer.module().frames(null, { first: explorer.state().step, count: 1, ...explorer.frameSize() }).frames[0];
      const heights = f.ops.filter((op) => op[0] === 'G').map((op) => {
        let most = 0;
        for (let k = 0; k < op[6].length; k += 3) {
          const ys = f.glyphs[op[6][k]].flatMap((s) => s.filter((v, i) => i % 2 === 1));
          if (ys.length) most = Math.max(most, Math.max(...ys) - Math.min(...ys));
        }
        return most;
      });
      return Math.min(...heights);
    })()`);
    await b.page('Emulation.setDeviceMetricsOverride', { width: 1366, height: 768, deviceScaleFactor: 1, mobile: false });
    try {
      const before = await smallestText();
      const at = await stepShown();
      await typeKey('f');
      await until('the frame composed at the screen\'s size', async () => (await b.evaluate('explorer.frameSize().width')) >= 1360);
      const seen = await b.evaluate(`(() => {
        const r = document.getElementById('frame').getBoundingClientRect();
        const shown = (id) => document.getElementById(id).getBoundingClientRect().height > 0;
        return [r.left, r.top, r.right, r.bottom, shown('grid'), shown('player'), shown('edge-table'), document.querySelector('header').getBoundingClientRect().height];
      })()`);
      assert.ok(seen[0] >= -0.5 && seen[1] >= -0.5 && seen[2] <= 1366.5 && seen[3] <= 768.5 && seen[2] - seen[0] >= 1360, `the frame is at ${seen.slice(0, 4)}`);
      assert.deepStrictEqual(seen.slice(4), [false, false, false, 0], 'the grid, the player, the tables, the header: seen');
      assert.equal(await staleValues(), 0, 'the frame shown is not the step drawn whole at its size');
      const text = await smallestText();
      assert.ok(text >= 9 && text >= 1.9 * before, `the smallest text is ${text.toFixed(1)} px tall (${before.toFixed(1)} in the page)`);
      await key('ArrowRight', 'ArrowRight');
      assert.equal(await stepShown(), at + 1);
      await until('the frame of the step drawn', async () => (await b.evaluate("document.getElementById('frame').dataset.step")) === String(at + 1));
      await typeKey('Escape');
      await until('the page again', async () => (await b.evaluate("document.querySelector('header').getBoundingClientRect().height")) > 0);
      await until('the frame composed at its column\'s size', async () => (await b.evaluate('explorer.frameSize().width')) < 1000);
      await key('ArrowLeft', 'ArrowLeft');
    } finally {
      await b.evaluate("document.body.classList.contains('presenting') && document.getElementById('present').click()");
      await b.page('Emulation.clearDeviceMetricsOverride');
    }
  });

  await check('accessibility: every control and canvas named, the canvases reached by Tab, each step said in a live region', async () => {
    // The names as the browser computes them (its accessibility tree), of everything a person
    // operates or sees as a picture.
    await b.page('Accessibility.enable');
    const { nodes } = await b.page('Accessibility.getFullAXTree', {});
    const roles = ['button', 'combobox', 'slider', 'textbox', 'spinbutton', 'image', 'img', 'ColorWell', 'checkbox'];
    const unnamed = nodes.filter((n) => !n.ignored && roles.includes(n.role?.value) && !(n.name?.value || '').trim()).map((n) => `${n.role.value} ${n.backendDOMNodeId}`);
    assert.deepStrictEqual(unnamed, [], 'controls without a name');
    const canvases = await b.evaluate("[...document.querySelectorAll('canvas')].filter((c) => c.getAttribute('aria-hidden') !== 'true').map((c) => [c.id, c.getAttribute('role'), (c.getAttribute('aria-label') || '').length > 10])");
    assert.deepStrictEqual(canvases, [['grid', 'img', true], ['frame', 'img', true]]);
    // Tab goes through the page and reaches both canvases.
    await b.evaluate('document.activeElement && document.activeElement.blur()');
    const reached = new Set();
    for (let i = 0; i < 60 && !(reached.has('grid') && reached.has('frame')); ++i) {
      await b.page('Input.dispatchKeyEvent', { type: 'rawKeyDown', key: 'Tab', code: 'Tab', windowsVirtualKeyCode: 9 });
      await b.page('Input.dispatchKeyEvent', { type: 'keyUp', key: 'Tab', code: 'Tab' });
      reached.add(await b.evaluate('document.activeElement.id'));
    }
    assert.ok(reached.has('grid') && reached.has('frame'), `Tab reached ${[...reached]}`);
    // With the frame focused the keys step, and the live region says the step: its number, and
    // for a scanline the row's span as the native trace has it.
    await b.evaluate("document.getElementById('frame').focus()");
    await key('Home', 'Home');
    const n = Number((await text('step-no')).match(/\/ (\d+)/)[1]);
    const live = await b.evaluate("(() => { const el = document.querySelector('[aria-live=polite]'); return el && el.id; })()");
    assert.equal(live, 'announce');
    const tri = (await b.evaluate('explorer.state()')).triangle;
    native(['trace', '--triangle', tri.map((v) => v.join(',')).join(' '), '--shading', 'flat', '-o', 'spoken.jsonl']);
    const rows = jsonl(fs.readFileSync(path.join(work, 'spoken.jsonl'), 'utf8')).filter((ev) => ev.type === 'scanline');
    let scanlines = 0;
    for (let k = 0; k < 25; ++k) {
      const said = await text('announce');
      assert.ok(said.startsWith(`Step ${k + 1} of ${n}: `), said);
      const m = said.match(/^Step \d+ of \d+: rows? (?:\d+\.\.)?(\d+) of triangle/);
      if (m) {
        const row = rows.find((ev) => ev.y === Number(m[1]));
        assert.ok(said.includes(row.span ? `Span: pixels ${row.span.x_begin} to ${row.span.x_end - 1}.` : 'No pixel'), `${said} / ${JSON.stringify(row.span)}`);
        ++scanlines;
      }
      await key('ArrowRight', 'ArrowRight');
    }
    assert.ok(scanlines >= 5, `${scanlines} scanline steps said`);
    assert.equal(await b.evaluate('document.activeElement.id'), 'frame');
    await key('End', 'End');
    await key('PageUp', 'PageUp');
  });

  await check("the step's frame drawn from RGBA blocks is the frame drawn from PNG blocks", async () => {
    // The page draws the frame's pixel blocks from bytes (putImageData, the clip applied by hand);
    // drawScantraceFrame with the PNG data URIs (drawImage under the canvas's clip) must give the
    // same pixels.
    const same = await b.evaluate(`(async () => {
      const st = explorer.module();
      const draw = new Function(st.canvasScript() + '; return drawScantraceFrame;')();
      const s = explorer.state();
      const f = st.frames(explorer.traceText(), { first: s.step, count: 1, source: 'the explorer\u2019s triangle', ...explorer.frameSize() }).frames[0];
      const c = document.createElement('canvas');
      c.width = f.w;
      c.height = f.h;
      const ctx = c.getContext('2d');
      await draw(ctx, f);
      const want = ctx.getImageData(0, 0, f.w, f.h).data;
      const got = explorer.framePixels();
      let differ = 0;
      for (let i = 0; i < want.length; ++i) if (want[i] !== got[i]) ++differ;
      return [got.length === want.length, differ, f.ops.filter((op) => op[0] === 'P').length];
    })()`);
    assert.equal(same[0], true, 'frame sizes differ');
    assert.ok(same[2] > 0, 'the frame has no pixel block');
    assert.equal(same[1], 0, `${same[1]} channel values differ`);
  });

  await check('the frame is composed at the size it is shown, and again when the window is resized', async () => {
    // Device pixels of the canvas's box (the device scale is 1 here), 16:9, at most 1280 wide.
    const shown = () => b.evaluate("(() => { const f = document.getElementById('frame'); return [f.width, f.height, f.clientWidth]; })()");
    const fits = ([w, h, css]) => {
      assert.equal(w, Math.max(320, Math.min(1280, css)));
      assert.equal(h, Math.max(180, Math.round((w * 9) / 16)));
    };
    const before = await shown();
    fits(before);
    assert.ok(before[0] < 1280, `the frame's column is ${before[2]} pixels wide in this window`);
    await b.page('Emulation.setDeviceMetricsOverride', { width: 900, height: 800, deviceScaleFactor: 1, mobile: false });
    try {
      await until('the frame composed at its new size', async () => (await shown())[0] !== before[0]);
      fits(await shown());
      assert.equal(await staleValues(), 0, 'the frame shown after the resize differs from the frame drawn whole at its size');
    } finally {
      await b.page('Emulation.clearDeviceMetricsOverride');
    }
    await until('the frame composed at its first size again', async () => (await shown())[0] === before[0]);
    assert.equal(await staleValues(), 0);
  });

  await check('a clipped RGBA block is drawn as its clipped PNG block, also on a scaled context', async () => {
    // No block of a triangle's replay has a clip; made here: a 9x7 block at (-2, -1) of the clip
    // [5, 4, 5, 3] (so clipped on every side), as bytes and as a PNG data URI (the test's encoder).
    const [w, h] = [9, 7];
    const rgba = new Uint8Array(w * h * 4);
    for (let i = 0; i < w * h; ++i) rgba.set([(i * 37) & 255, (i * 91) & 255, (i * 13 + 50) & 255, 255], i * 4);
    const uri = 'data:image/png;base64,' + encodePng({ width: w, height: h, rgba }).toString('base64');
    const differ = await b.evaluate(`(async () => {
      const draw = new Function(explorer.module().canvasScript() + '; return drawScantraceFrame;')();
      const data = new Uint8ClampedArray(${JSON.stringify(Array.from(rgba))});
      // At scale 1 (putImageData) and scale 2 (a page drawing at device pixels: drawImage).
      const pixels = async (block, scale) => {
        const c = document.createElement('canvas');
        c.width = 20 * scale;
        c.height = 12 * scale;
        const ctx = c.getContext('2d');
        ctx.setTransform(scale, 0, 0, scale, 0, 0);
        await draw(ctx, { w: 20, h: 12, bg: '#808080', ops: [['P', [5, 4, 5, 3], null, -2, -1, ${w}, ${h}, block]] });
        return ctx.getImageData(0, 0, c.width, c.height).data;
      };
      let n = 0;
      for (const scale of [1, 2]) {
        const [a, b] = [await pixels({ width: ${w}, height: ${h}, data }, scale), await pixels(${JSON.stringify(uri)}, scale)];
        for (let i = 0; i < a.length; ++i) if (a[i] !== b[i]) ++n;
      }
      return n;
    })()`);
    assert.equal(differ, 0, `${differ} channel values differ`);
  });

  await check('a block as runs and texels is drawn as its PNG, clipped, at scale 1 and 2', async () => {
    // The module hands the magnified cells over as runs of equal columns and rows with one texel
    // each (web/bindings_trace.cpp's block_runs); drawScantraceFrame stretches them. Made here:
    // runs [2, 1, 3, 3] × [3, 1, 3] of 12 texels, the 9x7 block they spell out written by the
    // test as a PNG, both drawn at (-2, -1) under the clip [5, 4, 5, 3].
    const [cols, rows] = [[2, 1, 3, 3], [3, 1, 3]];
    const [w, h] = [9, 7];
    const texels = new Uint8Array(cols.length * rows.length * 4);
    for (let i = 0; i < cols.length * rows.length; ++i) texels.set([(i * 61) & 255, (i * 29 + 7) & 255, (i * 113) & 255, 255], i * 4);
    const rgba = new Uint8Array(w * h * 4);
    const runOf = (runs, v) => { let k = 0; for (let at = runs[0]; at <= v; at += runs[++k]); return k; };
    for (let y = 0; y < h; ++y)
      for (let x = 0; x < w; ++x) rgba.set(texels.subarray((runOf(rows, y) * cols.length + runOf(cols, x)) * 4, (runOf(rows, y) * cols.length + runOf(cols, x)) * 4 + 4), (y * w + x) * 4);
    const uri = 'data:image/png;base64,' + encodePng({ width: w, height: h, rgba }).toString('base64');
    const differ = await b.evaluate(`(async () => {
      const draw = new Function(explorer.module().canvasScript() + '; return drawScantraceFrame;')();
      const runs = { width: ${w}, height: ${h}, cols: ${JSON.stringify(cols)}, rows: ${JSON.stringify(rows)}, texels: new Uint8ClampedArray(${JSON.stringify(Array.from(texels))}) };
      const pixels = async (block, scale, clip) => {
        const c = document.createElement('canvas');
        c.width = 20 * scale;
        c.height = 12 * scale;
        const ctx = c.getContext('2d');
        ctx.setTransform(scale, 0, 0, scale, 0, 0);
        await draw(ctx, { w: 20, h: 12, bg: '#808080', ops: [['P', clip, null, clip ? -2 : 3, clip ? -1 : 2, ${w}, ${h}, block]] });
        return ctx.getImageData(0, 0, c.width, c.height).data;
      };
      let n = 0;
      for (const scale of [1, 2])
        for (const clip of [null, [5, 4, 5, 3]]) {
          const [a, b] = [await pixels(runs, scale, clip), await pixels(${JSON.stringify(uri)}, scale, clip)];
          for (let i = 0; i < a.length; ++i) if (a[i] !== b[i]) ++n;
        }
      return n;
    })()`);
    assert.equal(differ, 0, `${differ} channel values differ`);
  });

  await check("text bitmaps kept between frames are keyed by what draws them, and bounded", async () => {
    // drawScantraceFrame draws a "G" op from a bitmap of its glyphs kept from an earlier frame
    // (viz/frame_json.cpp's scantraceTextBitmaps). Each variant of the step's frame changes one
    // thing an op's pixels depend on; drawn after the frame itself (its bitmaps kept), it must
    // give the pixels a fresh drawScantraceFrame (nothing kept) gives, and not the frame's.
    const r = await b.evaluate(`(() => {
      const st = explorer.module();
      const script = st.canvasScript() + '; return [drawScantraceFrame, scantraceTextBitmaps];';
      const f = st.frames(null, { first: explorer.state().step, count: 1, source: 'the explorer\u2019s triangle', blocks: 'rgba', ...explorer.frameSize() }).frames[0];
      const pixels = (draw, frame) => {
        const c = document.createElement('canvas');
        c.width = frame.w;
        c.height = frame.h;
        draw(c.getContext('2d'), frame);
        return c.getContext('2d').getImageData(0, 0, frame.w, frame.h).data;
      };
      const differ = (a, b) => { let n = 0; for (let i = 0; i < a.length; ++i) if (a[i] !== b[i]) ++n; return n; };
      const at = f.ops.findIndex((op) => op[0] === 'G' && op[6].length >= 9);
      // The variants: each a copy of the frame with op \`at\` changed.
      const variant = (change) => {
        const g = { ...f, ops: f.ops.slice(), glyphs: f.glyphs.slice() };
        g.ops[at] = f.ops[at].slice();
        g.ops[at][6] = Array.from(f.ops[at][6]);
        change(g.ops[at], g);
        return g;
      };
      const placed = (op) => op[6];
      const variants = {
        colour: variant((op) => { op[4] = op[4] === '#ff0000' ? '#0000ff' : '#ff0000'; }),
        width: variant((op) => { op[5] += 1; }),
        'a quarter pixel right': variant((op) => { for (let k = 1; k < placed(op).length; k += 3) placed(op)[k] += 0.25; }),
        'a quarter pixel down': variant((op) => { for (let k = 2; k < placed(op).length; k += 3) placed(op)[k] += 0.25; }),
        'three pixels right': variant((op) => { for (let k = 1; k < placed(op).length; k += 3) placed(op)[k] += 3; }),
        'its second glyph half a pixel right': variant((op) => { placed(op)[4] += 0.5; }),
        'its first glyph another': variant((op, g) => {
          const other = placed(op).findIndex((id, k) => k % 3 === 0 && JSON.stringify(g.glyphs[id]) !== JSON.stringify(g.glyphs[placed(op)[0]]));
          g.glyphs[placed(op)[0]] = g.glyphs[placed(op)[other]];
        }),
        'the strokes of its first glyph a tenth of a pixel right': variant((op, g) => {
          g.glyphs[placed(op)[0]] = g.glyphs[placed(op)[0]].map((s) => s.map((v, i) => (i % 2 ? v : v + 0.1)));
        }),
      };
      const [kept] = new Function(script)();
      const original = pixels(kept, f);
      const out = {};
      for (const [name, g] of Object.entries(variants)) {
        pixels(kept, f); // the frame's bitmaps kept
        const [fresh] = new Function(script)();
        const want = pixels(fresh, g);
        out[name] = [differ(pixels(kept, g), want), differ(original, want)];
      }
      // Bounded: at most 8 bitmaps, then at most 4000 pixels of them (unless one alone is more);
      // the frame drawn under those bounds is the frame drawn fresh.
      const bounded = {};
      for (const [limit, area] of [[8, 1 << 22], [512, 4000]]) {
        const [draw, bitmaps] = new Function(script)();
        draw.text = bitmaps(limit, area);
        const a = pixels(draw, f), b = pixels(draw, f);
        bounded[limit + ' bitmaps, ' + area + ' pixels'] = [differ(a, original), differ(b, original), draw.text.stats()];
      }
      return { out, bounded, stats: kept.text.stats() };
    })()`);
    for (const [name, [kept, changed]] of Object.entries(r.out)) {
      assert.ok(changed > 0, `${name}: the variant draws the frame's pixels (the check would be void)`);
      assert.equal(kept, 0, `${name}: drawn after the frame, ${kept} channel values differ from the variant drawn fresh`);
    }
    assert.ok(r.stats.hits > 0, `no bitmap was drawn again: ${JSON.stringify(r.stats)}`);
    for (const [name, [first, again, stats]] of Object.entries(r.bounded)) {
      assert.equal(first + again, 0, `${name}: ${first} and ${again} channel values differ from the frame drawn fresh`);
      const [limit, area] = name.match(/\d+/g).map(Number);
      assert.ok(stats.bitmaps <= limit && (stats.area <= area || stats.bitmaps === 1), `${name}: ${JSON.stringify(stats)}`);
      assert.ok(stats.misses > 85, `${name}: the frame's second drawing took its ops from bitmaps that had been dropped: ${JSON.stringify(stats)}`);
    }
  });

  await check('runs of filled rectangles drawn as one path, and ops of one clip under one clip, are the ops drawn one by one', async () => {
    // drawScantraceFrame fills consecutive filled rectangles of one colour as one path on an
    // untransformed context, and draws consecutive ops of one clip under one save and clip; an
    // empty rectangle of another colour and no clip put between every two ops breaks every run
    // and every group, so each op is drawn alone: the pixels must be the same.
    const r = await b.evaluate(`(() => {
      const st = explorer.module();
      const draw = new Function(st.canvasScript() + '; return drawScantraceFrame;')();
      const f = st.frames(null, { first: explorer.state().step, count: 1, source: 'x', blocks: 'rgba', encoding: 'binary', ...explorer.frameSize() }).frames[0];
      const apart = { ...f, ops: f.ops.flatMap((op) => [op, ['R', null, null, 0, 0, 0, 0, '#010203', -1]]) };
      const pixels = (frame) => {
        const c = document.createElement('canvas');
        c.width = frame.w;
        c.height = frame.h;
        draw(c.getContext('2d'), frame);
        return c.getContext('2d').getImageData(0, 0, frame.w, frame.h).data;
      };
      const [a, b] = [pixels(f), pixels(apart)];
      let n = 0;
      for (let i = 0; i < a.length; ++i) if (a[i] !== b[i]) ++n;
      let runs = 0;
      f.ops.forEach((op, i) => { const o = f.ops[i + 1]; if (op[0] === 'R' && op[8] < 0 && !op[1] && o && o[0] === 'R' && o[8] < 0 && !o[1] && o[7] === op[7]) ++runs; });
      // Clipped ops that follow one of the same clip, and clips that change from one op to the next.
      let grouped = 0, changed = 0;
      f.ops.forEach((op, i) => { const o = f.ops[i + 1]; if (op[1] && o && o[1]) (String(o[1]) === String(op[1]) ? ++grouped : ++changed); });
      return [n, runs, grouped, changed];
    })()`);
    assert.ok(r[1] > 100, `only ${r[1]} filled rectangles follow one of their colour`);
    assert.ok(r[2] > 100 && r[3] > 0, `${r[2]} clipped ops follow one of their clip, ${r[3]} one of another clip`);
    assert.equal(r[0], 0, `${r[0]} channel values differ`);
  });

  await check('a polygon: its trace, a dragged vertex and the winding rule are the native trace --polygon', async () => {
    // A self-crossing pentagon (a star): under non-zero its centre is inside, under even-odd not.
    const star = [[256, 40], [380, 440], [60, 190], [450, 190], [130, 440]];
    const arg = (p) => p.map((v) => v.join(',')).join(' ');
    await b.page('Page.navigate', { url: `file://${path.resolve(explorer)}#polygon=${star.map((v) => v.join(',')).join(';')}&winding=non-zero&shading=flat&step=5` });
    await until('the polygon page', () => b.evaluate("!!document.body && document.body.dataset.ready === '1' && explorer.state().mode === 'polygon'"));
    native(['trace', '--polygon', arg(star), '--winding', 'non-zero', '--shading', 'flat', '-o', 'star.jsonl']);
    assert.deepStrictEqual(jsonl(await b.evaluate('explorer.traceText()')), jsonl(fs.readFileSync(path.join(work, 'star.jsonl'), 'utf8')));
    // The centre (256, 250) is filled under non-zero: not the background's white.
    const centre = await b.evaluate('explorer.fillPixels().slice((250 * 512 + 256) * 4, (250 * 512 + 256) * 4 + 3)');
    assert.notDeepStrictEqual(centre, [255, 255, 255]);

    const from = await b.evaluate('explorer.vertexOnScreen(1)');
    const to = [from[0] + 40.4, from[1] - 61.3];
    await mouse('mousePressed', from);
    for (let i = 1; i <= 4; ++i) await mouse('mouseMoved', [from[0] + (to[0] - from[0]) * i / 4, from[1] + (to[1] - from[1]) * i / 4]);
    await mouse('mouseReleased', to);
    const moved = (await b.evaluate('explorer.state()')).polygon;
    assert.notDeepStrictEqual(moved[1], star[1]);
    assert.deepStrictEqual([moved[0], ...moved.slice(2)], [star[0], ...star.slice(2)]);
    native(['trace', '--polygon', arg(moved), '--winding', 'non-zero', '--shading', 'flat', '-o', 'star_moved.jsonl']);
    assert.deepStrictEqual(jsonl(await b.evaluate('explorer.traceText()')), jsonl(fs.readFileSync(path.join(work, 'star_moved.jsonl'), 'utf8')));
    assert.ok((await b.evaluate('location.hash')).includes(`polygon=${moved.map((v) => v.join(',')).join(';')}`));

    await b.evaluate("(() => { const w = document.getElementById('winding'); w.value = 'even-odd'; w.dispatchEvent(new Event('change')); })()");
    native(['trace', '--polygon', arg(moved), '--winding', 'even-odd', '--shading', 'flat', '-o', 'star_even_odd.jsonl']);
    assert.deepStrictEqual(jsonl(await b.evaluate('explorer.traceText()')), jsonl(fs.readFileSync(path.join(work, 'star_even_odd.jsonl'), 'utf8')));
    const centre2 = await b.evaluate('explorer.fillPixels().slice((250 * 512 + 256) * 4, (250 * 512 + 256) * 4 + 3)');
    assert.deepStrictEqual(centre2, [255, 255, 255]);
    // Back to the triangle the next checks expect.
    await b.evaluate("document.getElementById('triangle-mode').click()");
  });

  const scene = path.join(work, 'explorer_triangle.json');
  fs.writeFileSync(scene, await b.evaluate('explorer.scene()'));

  await check('the fill pixels are the native render', async () => {
    native(['render', 'explorer_triangle.json', '--shading', 'flat', '-o', 'explorer_triangle.png']);
    const want = decodePng(fs.readFileSync(path.join(work, 'explorer_triangle.png')));
    const got = await b.evaluate('explorer.fillPixels()');
    assert.equal(got.length, want.rgba.length);
    assert.ok(got.every((v, i) => v === want.rgba[i]), 'pixels differ');
  });

  await check('the grid shows the fill where the view puts it, grey where it leaves the grid uncovered, after a pan too', async () => {
    // What a person sees (a screenshot of one CSS pixel): the fill is its own canvas under the
    // grid's drawing, scaled and moved by the browser (explorer.js's placeFill).
    const r = await b.evaluate("(() => { const r = document.getElementById('grid').getBoundingClientRect(); return [r.left, r.top, r.width / 720]; })()");
    const seenAt = async ([x, y]) => {
      const shot = await b.page('Page.captureScreenshot', { format: 'png', clip: { x: Math.floor(x), y: Math.floor(y), width: 1, height: 1, scale: 1 } });
      return Array.from(decodePng(Buffer.from(shot.data, 'base64')).rgba.slice(0, 3));
    };
    // At the grid canvas's pixel (x, y), and at the centre of the image's pixel (x, y).
    const gridPixel = (x, y) => seenAt([r[0] + (x + 0.5) * r[2], r[1] + (y + 0.5) * r[2]]);
    const imagePixel = async (x, y) => seenAt(await b.evaluate(`explorer.pixelOnScreen(${x}, ${y})`));
    // Three image pixels either side of both ends of the triangle's span on rows 100 and 300: a
    // view placed or scaled a few pixels off shows the other side's colour there (the right edge
    // does not pass near the image's corner, where a wrong scale moves nothing).
    const fill = await b.evaluate('explorer.fillPixels()');
    const rgb = (x, y) => fill.slice((y * 512 + x) * 4, (y * 512 + x) * 4 + 3);
    const white = (x, y) => rgb(x, y).every((v) => v === 255);
    const span = (y) => {
      let x0 = 0;
      while (white(x0, y)) ++x0;
      let x1 = x0;
      while (!white(x1 + 1, y)) ++x1;
      return [x0, x1];
    };
    const edgesSeen = async (y, when) => {
      const [x0, x1] = span(y);
      assert.ok(x1 - x0 > 8, `row ${y}: a span of ${x1 - x0 + 1} pixels`);
      for (const [x, want] of [[x0 - 3, [255, 255, 255]], [x0 + 3, rgb(x0 + 3, y)], [x1 - 3, rgb(x1 - 3, y)], [x1 + 3, [255, 255, 255]]])
        assert.deepStrictEqual(await imagePixel(x, y), want, `${when}: row ${y}, pixel ${x} (the span is ${x0}..${x1})`);
    };
    for (const y of [100, 300]) await edgesSeen(y, 'the default view');
    // The default view: the 512 x 512 fill over the whole 720 x 720 grid, its white background in
    // the corner.
    assert.deepStrictEqual(await gridPixel(2, 2), [255, 255, 255]);
    // Panned 60 pixels right and down (a drag off the vertices): the strip it uncovers is grey,
    // and the fill moved with the view.
    const from = [r[0] + 200 * r[2], r[1] + 40 * r[2]], to = [from[0] + 60 * r[2], from[1] + 60 * r[2]];
    await mouse('mousePressed', from);
    await mouse('mouseMoved', to);
    await mouse('mouseReleased', to);
    assert.deepStrictEqual(await gridPixel(20, 20), [221, 221, 221]);
    assert.deepStrictEqual(await gridPixel(700, 700), [255, 255, 255]);
    await edgesSeen(300, 'after the pan');
    await mouse('mousePressed', to);
    await mouse('mouseMoved', from);
    await mouse('mouseReleased', from);
    assert.deepStrictEqual(await gridPixel(2, 2), [255, 255, 255]);
  });

  await check('a click on a pixel shows its why', async () => {
    // Mouse events land on whole CSS pixels: the pixel clicked is the one under that point, at
    // most one canvas pixel from the aim at this zoom.
    const at = (await b.evaluate('explorer.pixelOnScreen(150, 120)')).map(Math.round);
    await mouse('mousePressed', at);
    await mouse('mouseReleased', at);
    const pixel = await until('the why panel', () => b.evaluate("document.getElementById('why').dataset.pixel"));
    const [x, y] = pixel.split(',').map(Number);
    assert.ok(Math.abs(x - 150) <= 1 && Math.abs(y - 120) <= 1, `clicked ${pixel}`);
    const want = JSON.parse(native(['why', 'explorer_triangle.json', String(x), String(y), '--json', '--shading', 'flat']).stdout);
    assert.deepStrictEqual(JSON.parse(await text('why-json')), want);
  });

  await check("at 1366x768 a click's why is seen without scrolling: the answer first, then the command's text", async () => {
    await b.page('Emulation.setDeviceMetricsOverride', { width: 1366, height: 768, deviceScaleFactor: 1, mobile: false });
    try {
      await until('the grid at its new size', async () => (await b.evaluate("document.getElementById('grid').getBoundingClientRect().bottom")) < 768);
      for (const [x, y] of [[254, 106], [100, 30], [3, 500]]) {
        const at = (await b.evaluate(`explorer.pixelOnScreen(${x}, ${y})`)).map(Math.round);
        await mouse('mousePressed', at);
        await mouse('mouseReleased', at);
        const pixel = await until('the why panel', async () => {
          const p = await b.evaluate("document.getElementById('why').dataset.pixel");
          return p && p !== (await b.evaluate('window.lastWhy')) && p;
        });
        await b.evaluate(`window.lastWhy = ${JSON.stringify(pixel)}`);
        const [px, py] = pixel.split(',');
        // The command's own text (its stdout; the timing line is on stderr), line for line.
        const want = native(['why', 'explorer_triangle.json', px, py, '--shading', 'flat']).stdout;
        assert.equal(await text('why'), want);
        // The answer first: the text's last line (the final colour), as a sentence.
        const last = want.trim().split('\n').pop().trim();
        assert.equal(await text('why-answer'), `Pixel (${px}, ${py}): ${last}.`);
        // Seen: the answer and the text's first three lines inside the window, nothing scrolled,
        // the JSON behind its closed toggle.
        const seen = await b.evaluate(`(() => {
          const a = document.getElementById('why-answer').getBoundingClientRect(), w = document.getElementById('why').getBoundingClientRect();
          const left = document.getElementById('left');
          return [a.top >= 0, a.bottom <= innerHeight, w.top + 3 * 15 <= innerHeight, scrollY, left.scrollTop, document.getElementById('why-json-box').open];
        })()`);
        assert.deepStrictEqual(seen, [true, true, true, 0, 0, false], `answer inside, top, 3 lines of text seen, page and column scrolled, JSON open: ${seen}`);
      }
    } finally {
      await b.page('Emulation.clearDeviceMetricsOverride');
    }
  });

  await check("at high zoom each pixel's square is centred on its sample point: the pixels beside an edge on their side of it", async () => {
    // Pixel (x, y) is centred on the integer point (x, y) (docs/design.md §1). Where the page
    // draws a point of the plane is taken from the vertex handles alone (an affine map fitted to
    // the three vertices' screen positions), not from the page's own pixel placement: a fill drawn
    // half a pixel off shows the neighbour's colour in half of each square.
    const wheel = async (at, deltaY) => b.page('Input.dispatchMouseEvent', { type: 'mouseWheel', x: at[0], y: at[1], deltaX: 0, deltaY });
    const tri = (await b.evaluate('explorer.state()')).triangle;
    const toScreenAffine = async () => {
      const s = [];
      for (let i = 0; i < 3; ++i) s.push(await b.evaluate(`explorer.vertexOnScreen(${i})`));
      // Solve screen = A [x, y, 1] from the three correspondences (Cramer's rule).
      const [[x0, y0], [x1, y1], [x2, y2]] = tri;
      const det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
      return ([x, y]) => {
        const u = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / det;
        const v = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / det;
        return [0, 1].map((k) => s[0][k] + u * (s[1][k] - s[0][k]) + v * (s[2][k] - s[0][k]));
      };
    };
    let at = await b.evaluate('explorer.vertexOnScreen(1)');   // zoomed in around (250, 80)
    at = [at[0] + 2, at[1] + 12];
    for (let i = 0; i < 11; ++i) await wheel(at, -100);       // 1.25^11: about 16 screen pixels a pixel
    try {
      const place = await toScreenAffine();
      const seenAt = async ([x, y]) => {
        const shot = await b.page('Page.captureScreenshot', { format: 'png', clip: { x: Math.floor(x), y: Math.floor(y), width: 1, height: 1, scale: 1 } });
        return Array.from(decodePng(Buffer.from(shot.data, 'base64')).rgba.slice(0, 3));
      };
      const fill = await b.evaluate('explorer.fillPixels()');
      const rgb = (x, y) => fill.slice((y * 512 + x) * 4, (y * 512 + x) * 4 + 3);
      const white = (x, y) => rgb(x, y).every((v) => v === 255);
      // Screen distance from a point to the drawn outline's edges and handles: samples there
      // would see the outline's ink, not the pixel.
      const corners = tri.map(place);
      const nearInk = (p) => corners.some((c) => Math.hypot(p[0] - c[0], p[1] - c[1]) < 12) || corners.some((a, i) => {
        const c = corners[(i + 1) % 3], dx = c[0] - a[0], dy = c[1] - a[1];
        return Math.abs(dx * (p[1] - a[1]) - dy * (p[0] - a[0])) / Math.hypot(dx, dy) < 3;
      });
      const offsets = [-0.3, -0.2, 0.2, 0.3];
      let checked = 0;
      for (let y = 84; y <= 110; y += 2) {
        let x1 = 511;
        while (x1 > 0 && white(x1, y)) --x1;                 // the span's last pixel on row y
        for (const [x, want] of [[x1, rgb(x1, y)], [x1 + 1, [255, 255, 255]]]) {
          for (const dx of offsets) for (const dy of offsets) {
            const p = place([x + dx, y + dy]);
            if (nearInk(p)) continue;
            const got = await seenAt(p);
            assert.ok(got.every((v, k) => Math.abs(v - want[k]) <= 3), `row ${y}, pixel ${x} (the span ends at ${x1}), at (${x + dx}, ${y + dy}) in the plane: seen ${got}, the pixel is ${want}`);
            ++checked;
          }
        }
      }
      assert.ok(checked >= 100, `only ${checked} points away from the outline`);
      // A click on the point (254, 106) of the plane (edge e1 crosses row 106 at 254.06) is a
      // click on pixel (254, 106), whose why says it is covered: the square drawn there is filled.
      const click = place([254.2, 106.2]).map(Math.round);
      await mouse('mousePressed', click);
      await mouse('mouseReleased', click);
      await until('the why panel for (254, 106)', () => b.evaluate("document.getElementById('why').dataset.pixel === '254,106'"));
      const why = JSON.parse(await text('why-json'));
      const want = JSON.parse(native(['why', 'explorer_triangle.json', '254', '106', '--json', '--shading', 'flat']).stdout);
      assert.deepStrictEqual(why, want);
      assert.ok(!white(254, 106), 'pixel (254, 106) is filled');
    } finally {
      for (let i = 0; i < 11; ++i) await wheel(at, 100);
    }
  });

  // Files go in through the page's file input, as a drop or a chooser gives them.
  const setFile = async (file) => {
    const { root } = await b.page('DOM.getDocument', {});
    const { nodeId } = await b.page('DOM.querySelector', { nodeId: root.nodeId, selector: '#open' });
    await b.page('DOM.setFileInputFiles', { nodeId, files: [file] });
  };

  await check('a malformed scene shows the CLI line and the page keeps working', async () => {
    const bad = path.join(work, 'broken.json');
    fs.writeFileSync(bad, '{"width": 10, "height": 10, "vertices": [[0, 0]], "faces": [[0, 1, 2]]}');
    const line = native(['render', 'broken.json', '-o', 'broken.png'], [1]).stderr.trim().replace(/^scantrace: /, '');
    await setFile(bad);
    await until('the error line', async () => (await text('error')).length > 0);
    assert.equal(await text('error'), line);
    await b.evaluate("document.getElementById('triangle-mode').click()");
    await until('the error cleared', async () => (await text('error')) === '');
  });

  await check('an image for the open scene is diffed as diff --json diffs it', async () => {
    await setFile(scene);
    await until('the scene open', async () => (await b.evaluate('explorer.state().mode')) === 'scene');
    // A student-style image: the closed rule on whole pixels, and a block of wrong colours.
    native(['render', 'explorer_triangle.json', '--fill-rule', 'closed', '--subpixel-bits', '0', '-o', 'student.png']);
    const img = decodePng(fs.readFileSync(path.join(work, 'student.png')));
    for (let y = 100; y < 130; ++y) for (let x = 100; x < 140; ++x) img.rgba[(y * img.width + x) * 4 + 1] ^= 0x55;
    fs.writeFileSync(path.join(work, 'student.png'), encodePng(img));
    const want = JSON.parse(native(['diff', 'explorer_triangle.json', 'student.png', '--json', '--shading', 'flat'], [0, 3]).stdout);
    await setFile(path.join(work, 'student.png'));
    await until('the diff report', async () => (await text('diff-verdict')).length > 0);
    await b.evaluate("document.getElementById('diff-json-box').open = true");
    await until('the JSON in its toggle', async () => (await text('diff-json')).startsWith('{'));
    assert.deepStrictEqual(JSON.parse(await text('diff-json')), want);
  });

  await check("a diff is shown as its summary: the command's verdict and counts, a legend of the picture's colours, the JSON closed", async () => {
    await b.evaluate("document.getElementById('diff-json-box').open = false");
    // The command's Markdown summary: its verdict line and its table of categories.
    const md = native(['diff', 'explorer_triangle.json', 'student.png', '--shading', 'flat'], [0, 3]).stdout;
    // The verdict: the mistakes the command names first ("- **sentence** (evidence)" lines before
    // its counts), or, when it names none, its counts line.
    const countsLine = md.match(/^\*\*(\d+ of \d+ pixels differ.*)\*\*$/m);
    const named = [...md.slice(0, countsLine.index).matchAll(/^- \*\*(.*?)\*\*/gm)].map((m) => m[1]);
    assert.equal(await text('diff-verdict'), named.length ? named.join('; ') : countsLine[1]);
    if (named.length) assert.ok((await text('diff-lines')).includes(countsLine[1]), 'the counts follow the verdict');
    const counts = Object.fromEntries([...md.matchAll(/^\| `(\w+)` \| (\d+) \|/gm)].map((m) => [m[1], Number(m[2])]));
    assert.ok(Object.keys(counts).length >= 2, md);
    const legend = await b.evaluate("[...document.querySelectorAll('#diff-legend li')].map((li) => [li.dataset.category, li.textContent, li.dataset.rgb, getComputedStyle(li.firstChild).backgroundColor])");
    assert.deepStrictEqual(legend.map((l) => l[0]).sort(), Object.keys(counts).sort());
    // Each colour of the legend is the colour the picture over the grid has at a pixel of its
    // category (the report's first run of it), and its swatch is painted in it.
    const report = JSON.parse(native(['diff', 'explorer_triangle.json', 'student.png', '--json', '--shading', 'flat'], [0, 3]).stdout);
    const picture = await b.evaluate('Array.from(explorer.module().lastDiffPicture.rgba)');
    for (const [category, label, rgb, css] of legend) {
      assert.ok(label.includes(`${counts[category]}`), `${category}: '${label}' lacks the count ${counts[category]}`);
      const run = report.category_map.runs.find((r) => report.category_map.legend[r[2]] === category);
      assert.equal(picture.slice(run[0] * 4, run[0] * 4 + 3).join(','), rgb, `${category}: the picture's colour`);
      assert.equal(css, `rgb(${rgb.split(',').join(', ')})`);
    }
    // The JSON is not what is seen: the toggle closed, the summary's box shorter than a window.
    const [open, height] = await b.evaluate("[document.getElementById('diff-json-box').open, document.getElementById('diff-box').getBoundingClientRect().height]");
    assert.equal(open, false);
    assert.ok(height < 400, `the diff's box is ${height} px tall`);
  });

  // A .npy file as numpy.save writes it (format 1.0): the header dict padded to 64 bytes.
  const npy = (descr, shape, data) => {
    let dict = `{'descr': '${descr}', 'fortran_order': False, 'shape': (${shape.join(', ')}), }`;
    dict += ' '.repeat(63 - ((10 + dict.length) % 64)) + '\n';
    const head = Buffer.alloc(10);
    Buffer.from('\x93NUMPY', 'latin1').copy(head);
    head[6] = 1;
    head.writeUInt16LE(dict.length, 8);
    return Buffer.concat([head, Buffer.from(dict, 'latin1'), Buffer.from(data)]);
  };

  // Bad input the command refuses before decoding: the page shows `scantrace diff`'s line for the
  // same files (its 'scantrace: ' prefix aside) and keeps working: the next good file is diffed.
  await check("bad input shows scantrace diff's line and the page keeps working", async () => {
    // A PNG whose header declares 100000 x 100000 pixels (its IHDR's CRC right; one short IDAT).
    const ihdr = Buffer.alloc(13);
    ihdr.writeUInt32BE(100000, 0);
    ihdr.writeUInt32BE(100000, 4);
    ihdr.set([8, 2, 0, 0, 0], 8);
    fs.writeFileSync(path.join(work, 'huge.png'), Buffer.concat([pngSignature, pngChunk('IHDR', ihdr),
      pngChunk('IDAT', zlib.deflateSync(Buffer.alloc(10))), pngChunk('IEND', Buffer.alloc(0))]));
    // An object array: numpy.save(allow_pickle=True) writes its pickle after the header.
    fs.writeFileSync(path.join(work, 'pickled.npy'), npy('|O', [2, 2, 3], Buffer.from('\x80\x04\x95\x00cbuiltins\neval\n.', 'latin1')));
    const bad = path.join(work, 'broken_scene.json');
    fs.writeFileSync(bad, '{"width": 512, "vertices": [');
    for (const [file, scene] of [['huge.png', 'explorer_triangle.json'], ['pickled.npy', 'explorer_triangle.json'], ['student.png', 'broken_scene.json']]) {
      const line = native(['diff', scene, file], [1]).stderr.trim().split('\n').pop().replace(/^scantrace: /, '');
      if (scene === 'broken_scene.json') {
        await setFile(bad);
      } else {
        await setFile(scene === 'explorer_triangle.json' ? path.join(work, 'explorer_triangle.json') : scene);
        await until('the scene open', async () => (await b.evaluate('explorer.state().mode')) === 'scene' && (await text('error')) === '');
        await setFile(path.join(work, file));
      }
      await until(`the error line for ${file}`, async () => (await text('error')).length > 0);
      assert.equal(await text('error'), line);
    }
  });

  await check('a .npy image for the open scene is diffed as diff --json diffs it', async () => {
    await setFile(path.join(work, 'explorer_triangle.json'));
    await until('the scene open', async () => (await b.evaluate('explorer.state().mode')) === 'scene' && (await text('error')) === '');
    // The student image of the PNG check as the course hands images in: float64, H x W x 3.
    const img = decodePng(fs.readFileSync(path.join(work, 'student.png')));
    const values = new Float64Array(img.width * img.height * 3);
    for (let i = 0, k = 0; i < img.width * img.height; ++i)
      for (let c = 0; c < 3; ++c) values[k++] = img.rgba[i * 4 + c] / 255;
    fs.writeFileSync(path.join(work, 'student.npy'), npy('<f8', [img.height, img.width, 3], new Uint8Array(values.buffer)));
    const want = JSON.parse(native(['diff', 'explorer_triangle.json', 'student.npy', '--json', '--shading', 'flat'], [0, 3]).stdout);
    await b.evaluate("document.getElementById('diff-verdict').textContent = ''; document.getElementById('diff-json-box').open = true");
    await setFile(path.join(work, 'student.npy'));
    await until('the diff report', async () => (await text('diff-json')).startsWith('{'));
    assert.deepStrictEqual(JSON.parse(await text('diff-json')), want);
    assert.equal(await text('error'), '');
  });

  await check("a scene link: the demo at the link's step; a file named by the link warned of, opened at the link's step once dropped", async () => {
    const open = async (hash) => {
      // By way of a blank page: the same file with another hash would only change the hash.
      await b.page('Page.navigate', { url: 'about:blank' });
      await until('the blank page', () => b.evaluate("location.href === 'about:blank'"));
      await b.page('Page.navigate', { url: `file://${path.resolve(explorer)}${hash}` });
      await until('the page', () => b.evaluate("!!document.body && document.body.dataset.ready === '1'"));
    };
    await open('#scene=demo&shading=flat&step=4');
    assert.equal((await b.evaluate('explorer.state()')).mode, 'scene');
    assert.match(await text('step-no'), /^step 4 \//);
    assert.equal(await b.evaluate("document.getElementById('notice').hidden"), true);
    // A file's name: the page cannot read it; the warning says which file and how to open it.
    fs.copyFileSync(path.join(work, 'explorer_triangle.json'), path.join(work, 'lecture_scene.json'));
    await open('#scene=lecture_scene.json&shading=flat&step=5');
    const notice = await b.evaluate("(() => { const el = document.getElementById('notice'); const r = el.getBoundingClientRect(); return [el.hidden, el.textContent, r.top >= 0 && r.bottom <= innerHeight && r.height > 10]; })()");
    assert.equal(notice[0], false, 'no warning');
    assert.ok(notice[2], 'the warning is not in the window');
    for (const words of ['lecture_scene.json', 'step 5', 'Drop']) assert.ok(notice[1].includes(words), notice[1]);
    assert.ok((await b.evaluate('location.hash')).includes('scene=lecture_scene.json'), 'the address lost the link');
    await setFile(path.join(work, 'lecture_scene.json'));
    await until('the scene open', async () => (await b.evaluate('explorer.state().mode')) === 'scene');
    assert.match(await text('step-no'), /^step 5 \//);
    assert.equal(await b.evaluate("document.getElementById('notice').hidden"), true);
    const hash = await b.evaluate('location.hash');
    assert.ok(hash.includes('scene=lecture_scene.json') && hash.includes('step=5'), hash);
  });

  await check('a phone (390x844): one column, no horizontal scroll, a finger drags a vertex from 11 CSS px away', async () => {
    await b.page('Emulation.setDeviceMetricsOverride', { width: 390, height: 844, deviceScaleFactor: 1, mobile: true });
    await b.page('Emulation.setTouchEmulationEnabled', { enabled: true, maxTouchPoints: 5 });
    try {
      await b.page('Page.navigate', { url: 'about:blank' });
      await until('the blank page', () => b.evaluate("location.href === 'about:blank'"));
      await b.page('Page.navigate', { url: `file://${path.resolve(explorer)}#triangle=20,20;250,80;300,400&shading=flat&step=3` });
      await until('the page', () => b.evaluate("!!document.body && document.body.dataset.ready === '1'"));
      const layout = await b.evaluate(`(() => {
        const box = (el) => el.getBoundingClientRect();
        // The frame is drawn wider than a phone, its text readable, in a box that scrolls.
        const wide = [...document.querySelectorAll('header *, #player *, #grid, #frame-box')].filter((el) => box(el).width > 0 && box(el).right > innerWidth + 0.5).map((el) => el.id || el.tagName);
        return { scroll: document.documentElement.scrollWidth, wide, grid: box(document.getElementById('grid')).toJSON(), frame: box(document.getElementById('frame')).toJSON() };
      })()`);
      assert.ok(layout.scroll <= 390, `the page is ${layout.scroll} px wide`);
      assert.deepStrictEqual(layout.wide, [], 'cut off on the right');
      assert.ok(layout.grid.width >= 370 && layout.frame.top >= layout.grid.bottom, `grid ${JSON.stringify(layout.grid)}, frame ${JSON.stringify(layout.frame)}`);
      // A finger put down 11 CSS px right of vertex 2 (inside a 24-px target) and moved.
      const v = await b.evaluate('explorer.vertexOnScreen(2)');
      const scrolled = await b.evaluate('scrollY');
      const from = [v[0] + 11, v[1]];
      const touch = (type, [x, y]) => b.page('Input.dispatchTouchEvent', { type, touchPoints: type === 'touchEnd' ? [] : [{ x, y, id: 1 }] });
      await touch('touchStart', from);
      for (let i = 1; i <= 4; ++i) await touch('touchMove', [from[0] - 10 * i, from[1] - 15 * i]);
      await touch('touchEnd', from);
      const tri = (await b.evaluate('explorer.state()')).triangle;
      assert.notDeepStrictEqual(tri[2], [300, 400], 'the finger did not move vertex 2');
      assert.deepStrictEqual(tri.slice(0, 2), [[20, 20], [250, 80]]);
      assert.equal(await b.evaluate('scrollY'), scrolled, 'the drag scrolled the page');
      assert.ok((await b.evaluate('document.title')).startsWith(`scantrace explorer: triangle ${tri.map((p) => `(${p.join(',')})`).join(' ')}, step 3 of `), 'the title after the drag');
      native(['trace', '--triangle', tri.map((p) => p.join(',')).join(' '), '--shading', 'flat', '-o', 'touched.jsonl']);
      assert.deepStrictEqual(jsonl(await b.evaluate('explorer.traceText()')), jsonl(fs.readFileSync(path.join(work, 'touched.jsonl'), 'utf8')));
    } finally {
      await b.page('Emulation.setTouchEmulationEnabled', { enabled: false });
      await b.page('Emulation.clearDeviceMetricsOverride');
    }
  });

  await check('no console error, no exception, no network request', async () => {
    assert.deepStrictEqual(problems, []);
  });
} finally {
  await b.close();
}
console.log(`${checks.passed} checks passed${process.exitCode ? ', some FAILED' : ''}`);
