// The trace page's module (scantrace_player: web/player/player_module.cpp, docs/web.md) against
// the full module (scantrace_wasm), in Node:
// - it carries only the player's functions: its glue receives no other st_* export (no render,
//   trace, why, diff, scene reader), and it has no file system;
// - it lists the same steps and composes the same frames as the full module's frames() (the
//   decoded canvas JSON compared, PNG blocks included): every step of the course triangle (47)
//   and of a small triangle one row a step (33), a triangle's trace replayed in `scene` mode, and
//   11 of the demo scene's 91 painter's batches with a marked pixel;
// - a malformed trace gets a one-line message naming the trace and its line, and the module
//   keeps working.
//
//   node node_player.mjs WEB_DIR
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

import { check, summary } from './check.mjs';
// The player core's checks (keys, stepping, g, play and speed) run first.
import './node_player_core.mjs';

const [webDir] = process.argv.slice(2);
const { load } = await import(pathToFileURL(path.join(webDir, 'scantrace.mjs')));
const { loadPlayer } = await import(pathToFileURL(path.join(webDir, 'player_api.mjs')));
const full = await load();
const pm = await loadPlayer(fs.readFileSync(path.join(webDir, 'scantrace_player.wasm')));

check("the player's module receives only the player's exports, and no file system", () => {
  const glue = fs.readFileSync(path.join(webDir, 'scantrace_player.mjs'), 'utf8');
  const exported = [...new Set([...glue.matchAll(/Module\["(_st_\w+)"\]/g)].map((m) => m[1]))].sort();
  assert.deepStrictEqual(exported, ['_st_page_error', '_st_page_frame', '_st_page_open', '_st_page_text',
    '_st_page_text_size']);
  // The full module's glue, read the same way, names its functions (the pattern finds them).
  const fullGlue = fs.readFileSync(path.join(webDir, 'scantrace_wasm.mjs'), 'utf8');
  for (const name of ['_st_render', '_st_trace', '_st_why', '_st_diff', '_st_frames'])
    assert.ok(fullGlue.includes(`Module["${name}"]`), name);
  assert.ok(!/\bMEMFS\b/.test(glue), 'the glue carries MEMFS');
});

// Steps `which` (all by default) of the trace of `input` under `options`, from both modules: the
// player's from the trace's text, the full module's from the same trace kept in its memory
// (frames(null): not parsed again for every step; web/tests/node_compare.mjs holds a kept trace's
// frames to those of its text).
function compare(what, input, options, which = null) {
  check(`${what}: the same steps and frames as the full module`, () => {
    const t0 = Date.now();
    const traceText = full.traceText(input, { keep: true });
    const expected = full.frames(null, { ...options, count: 0 }).steps;
    const { steps } = pm.open(traceText, options);
    assert.deepStrictEqual(steps, expected);
    const indices = which ? which(steps.length) : steps.map((_, i) => i);
    for (const i of indices) {
      const want = full.frames(null, { ...options, first: i, count: 1 }).frames[0];
      assert.deepStrictEqual(pm.frame(i), want, `step ${i + 1} of ${steps.length}`);
    }
    console.log(`${what}: ${indices.length} of ${steps.length} steps compared (${Date.now() - t0} ms)`);
  });
}

const course = { triangle: [[20, 20], [250, 80], [300, 400]] };
compare('the course triangle', course, { width: 1280, height: 720, source: 'course' });
const small = { triangle: [[2.3, 1.2], [29, 9.5], [8, 27.6]], width: 32, height: 30 };
compare('a small triangle, one row a step', small,
  { width: 640, height: 360, rows_per_step: 1, source: 't.jsonl' });
compare('a triangle replayed in scene mode', small, { width: 960, height: 540, mode: 'scene', source: 't.jsonl' });
// A scene's steps are its painter's batches: every tenth, and the last ones (the finished image,
// the end card).
compare('the demo scene, a pixel marked', { scene: full.demoScene() },
  { width: 1280, height: 720, marked_pixel: [200, 150], source: 'demo_scene.json' },
  (n) => [...Array(n).keys()].filter((i) => i % 10 === 0 || i >= n - 2));

check("the full module's canvas script is web/player/frame_draw.js", () =>
  assert.strictEqual(full.canvasScript(), fs.readFileSync(new URL('../player/frame_draw.js', import.meta.url), 'utf8').replace(/^(\/\/.*\n)+/, '')));

check('a malformed trace: one line naming it and its line; the module keeps working', () => {
  const bad = full.traceText(course).split('\n').slice(0, 3).join('\n') + '\n{"type": "scanline", \n';
  assert.throws(() => pm.open(bad, { source: 'bad.jsonl' }), (e) => {
    assert.strictEqual(e.status, 1);
    assert.match(e.message, /^bad\.jsonl:4: /);
    assert.ok(!e.message.includes('\n'), e.message);
    return true;
  });
  assert.throws(() => pm.frame(0), /no trace opened/);
  assert.strictEqual(pm.open(full.traceText(small), { width: 640, height: 360 }).steps.length, 33);
  assert.throws(() => pm.frame(1e6), (e) => e.status === 2);
});

console.log(summary());
