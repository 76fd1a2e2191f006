// The JavaScript API checks its arguments as the command does (issue 46 #13, #14, #16): a pixel
// coordinate or a tolerance the command refuses is a ScantraceError with the command's words (the
// native command's stderr is the reference), in the API layer and in the module under it (its
// st_* functions called directly); every error is a ScantraceError; a trace's text and frames
// take the command's byte cap and its warning; an image whose header declares another size than
// the scene's canvas gets the command's canvas_size report without being decoded.
//
//   node node_arguments.mjs WEB_DIR SCANTRACE WORK_DIR DEMO_SCENE.json
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

import { check, summary } from './check.mjs';

const [webDir, scantraceArg, work, demoScene] = process.argv.slice(2);
const scantrace = path.resolve(scantraceArg);
const { load, ScantraceError } = await import(pathToFileURL(path.join(webDir, 'scantrace.mjs')));
const warnings = [];
const st = await load({ printErr: (line) => warnings.push(line) });
fs.mkdirSync(work, { recursive: true });
fs.copyFileSync(demoScene, path.join(work, 'demo.json'));
const demo = { name: 'demo.json', data: fs.readFileSync(demoScene) };

// The native command in WORK_DIR: {status, line}, line its first stderr line without the
// "scantrace: usage error: " / "scantrace: error: " prefix.
function native(args) {
  const r = spawnSync(scantrace, args, { encoding: 'utf8', cwd: work, maxBuffer: 1 << 26 });
  const line = r.stderr.split('\n')[0].replace(/^scantrace: (usage error|error|warning): /, '');
  return { status: r.status, line, stdout: r.stdout, stderr: r.stderr };
}

// `f` throws a ScantraceError of `status` whose message is `message`.
function throwsExactly(f, status, message) {
  assert.throws(f, (e) => {
    assert.ok(e instanceof ScantraceError, `not a ScantraceError: ${e && e.constructor && e.constructor.name}: ${e && e.message}`);
    assert.equal(e.message, message);
    assert.equal(e.status, status);
    return true;
  });
}

// A PNG of a few dozen bytes declaring width x height: IHDR, a one-byte IDAT (decoded, an error)
// and IEND.
function tinyPng(width, height) {
  const chunk = (type, data) => {
    const b = Buffer.alloc(12 + data.length);
    b.writeUInt32BE(data.length, 0);
    b.write(type, 4, 'latin1');
    data.copy(b, 8);
    return b;
  };
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(width, 0);
  ihdr.writeUInt32BE(height, 4);
  ihdr[8] = 8;
  ihdr[9] = 2;
  return Buffer.concat([Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]), chunk('IHDR', ihdr), chunk('IDAT', Buffer.from('x')), chunk('IEND', Buffer.alloc(0))]);
}

// why: X and Y as the command reads them. The command gets String(v), the text a user would type.
for (const [v, axis] of [[2 ** 32 + 100, 'X'], [NaN, 'X'], [1e308, 'X'], ['abc', 'X'], [100.9, 'X'], [-1, 'X'], [Infinity, 'Y'], [200.5, 'Y']]) {
  check(`why ${axis} = ${String(v)}`, () => {
    const args = axis === 'X' ? [v, 200] : [100, v];
    const cli = native(['why', 'demo.json', String(args[0]), String(args[1])]);
    assert.equal(cli.status, 2, cli.stderr);
    throwsExactly(() => st.why(demo, ...args), 2, cli.line);
  });
}
check('why: a pixel off the canvas is the command\'s bad input', () => {
  const cli = native(['why', 'demo.json', '600', '200']);
  assert.equal(cli.status, 1, cli.stderr);
  throwsExactly(() => st.why(demo, 600, 200), 1, cli.line);
  // And a right one still answers, for the pixel asked (not a truncated one).
  assert.deepEqual(st.why(demo, 100, 200).pixel, [100, 200]);
});
check('why: the module itself refuses what the API layer would (no truncation under it)', () => {
  const scene = st._sceneFile(demo);
  for (const v of [2 ** 32 + 100, NaN, 1e308, 100.9, -1])
    assert.throws(() => st._call('why', [scene, v, 200, '{}']), (e) => {
      assert.ok(e instanceof ScantraceError);
      assert.equal(e.status, 2);
      assert.match(e.message, /^X: must be a pixel column, 0 to the canvas width - 1 \(got "/);
      return true;
    }, String(v));
});

// diff: the tolerance as `diff --tolerance` takes it.
const png = path.join(work, 'demo.png');
native(['render', 'demo.json', '-o', png]);
const black = { width: 512, height: 512, rgba: new Uint8ClampedArray(512 * 512 * 4).fill(255, 0, 0) };
for (let i = 3; i < black.rgba.length; i += 4) black.rgba[i] = 255;
for (const t of [-1, 1e308, NaN, 2, Infinity]) {
  check(`diff tolerance ${String(t)}`, () => {
    const cli = native(['diff', 'demo.json', 'demo.png', '--tolerance', String(t)]);
    assert.equal(cli.status, 2, cli.stderr);
    throwsExactly(() => st.diff(demo, black, { tolerance: t }), 2, cli.line.replace(/^--/, ''));
  });
}
check('diff: the module itself refuses a tolerance the API layer would', () => {
  const scene = st._sceneFile(demo);
  const rgba = new Uint8Array(black.rgba.buffer);
  for (const [json, message] of [
    ['{"tolerance": null}', 'tolerance: "null" is not a finite number'],
    ['{"tolerance": -1}', 'tolerance: Value -1 not in range 0.000000 to 1.000000'],
    ['{"tolerance": 1e308}', 'tolerance: Value 1e+308 not in range 0.000000 to 1.000000'],
    ['{"tolerance": "x"}', 'tolerance: ""x"" is not a finite number'],
  ])
    throwsExactly(() => st._call('diff', [scene, rgba, 512, 512, 'x.png', json]), 2, message);
  // An option of another type: a ScantraceError without nlohmann's "[json.exception...]".
  assert.throws(() => st._call('diff', [scene, rgba, 512, 512, 'x.png', '{"undo": "yes"}']), (e) =>
    e instanceof ScantraceError && e.status === 2 && !e.message.includes('json.exception'));
});

// Every error is a ScantraceError.
check('names "." and ".." and other wrong arguments are ScantraceErrors', () => {
  for (const name of ['.', '..', 'dir/..'])
    throwsExactly(() => st.render({ name, data: demo.data }), 2, `scene: "${name}" is not a file name`);
  throwsExactly(() => st.checkImage({ name: '..', data: new Uint8Array(4) }), 2, 'image file: ".." is not a file name');
  for (const f of [() => st.diff(demo, null), () => st.frames(42), () => st.render(demo, null), () => st.keptStep(1.5, 2), () => st.trace({ triangle: 5 })])
    assert.throws(f, (e) => e instanceof ScantraceError, String(f));
  // The module still works.
  assert.equal(st.render(demo).width, 512);
});

// traceText and frames: the command's byte cap and warning.
check('traceText under max_bytes is `trace --max-bytes`, with its warning', () => {
  const tri = ['--triangle', '20,20 250,80 300,400', '--level', 'pixel', '--max-bytes', '4096', '-o', 'capped.jsonl'];
  const cli = native(['trace', ...tri]);
  assert.equal(cli.status, 0, cli.stderr);
  const want = fs.readFileSync(path.join(work, 'capped.jsonl'), 'utf8');
  const warning = cli.stderr.split('\n').find((l) => l.includes('truncated')).replace(/^scantrace: /, '');
  const input = { triangle: [[20, 20], [250, 80], [300, 400]] };
  for (const keep of [false, true]) {
    warnings.length = 0;
    const text = st.traceText(input, { level: 'pixel', max_bytes: 4096, keep });
    assert.equal(text, want, `keep ${keep}`);
    assert.ok(text.length <= 4096 + 100);
    // Its words, the output's name and the option's as the API names them.
    assert.equal(st.lastWarning, warning.replace('capped.jsonl', 'trace').replace('--max-bytes', 'max_bytes'));
    assert.deepEqual(warnings, [st.lastWarning]);
  }
  st.traceText(input, { level: 'triangle' });
  assert.equal(st.lastWarning, null);
  for (const b of [5, 1.5, 2 ** 51]) {
    const c = native(['trace', '--triangle', '1,1 5,5 1,5', '--max-bytes', String(b), '-o', 'x.jsonl']);
    assert.equal(c.status, 2);
    throwsExactly(() => st.traceText(input, { max_bytes: b }), 2, c.line.replace(/^--max-bytes/, 'max_bytes'));
  }
});
check('frames: past max_bytes, an error naming it', () => {
  const text = st.traceText({ triangle: [[20, 20], [250, 80], [300, 400]] });
  assert.throws(() => st.frames(text, { max_bytes: 1024 }), (e) =>
    e instanceof ScantraceError && e.status === 1 && e.message.includes('max_bytes 1024'));
  assert.equal(st.frames(text, { first: 2, count: 1 }).frames.length, 1);
});

// The pre-check: a header whose size is not the canvas's is the command's report, nothing decoded.
check('checkImage with the scene: a 16000x16000 PNG header is diff\'s canvas_size report', () => {
  const big = tinyPng(16000, 16000);
  fs.writeFileSync(path.join(work, 'big.png'), big);
  const cli = native(['-q', 'diff', 'demo.json', 'big.png', '--json']);
  assert.equal(cli.status, 3, cli.stderr);
  const want = JSON.parse(cli.stdout);
  assert.equal(want.global[0].kind, 'canvas_size');
  const t0 = Date.now();
  const got = st.checkImage({ name: 'big.png', data: new Uint8Array(big) }, demo);
  assert.ok(Date.now() - t0 < 2000);
  assert.deepStrictEqual(got.report, want);
  assert.equal(got.width, 16000);
  assert.equal(st.lastDiffPicture.width, 512);
  // A decoded image of another size gets the same report as its file.
  const small = { width: 4, height: 3, rgba: new Uint8Array(48), name: 'small.png' };
  const report = st.diff(demo, small);
  assert.deepEqual(report.global, [{ kind: 'canvas_size', text: "the image is 4x3, the scene's canvas is 512x512", undone: false }]);
  assert.equal(report.compared_pixels, 0);
});

console.log(summary());
