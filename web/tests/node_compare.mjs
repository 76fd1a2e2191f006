// The WebAssembly build is the same rasterizer (issue 33; docs/web.md): in Node, the module's
// render, trace, why and diff are compared with the native `scantrace` command's outputs:
// bit-identical pixels (the PNG decoded here), the same trace events (decoded JSON), the same
// why / diff documents.
//
//   node node_compare.mjs WEB_DIR SCANTRACE WORK_DIR [DEMO_SCENE.json]
// The course scene (/work/shared/data/hw1_2024.json) is compared when it exists.
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

import { decodePng, encodePng } from './png.mjs';
import { hardCases, manyFaces } from './scenes.mjs';

const [webDir, scantraceArg, work, demoScene] = process.argv.slice(2);
const scantrace = path.resolve(scantraceArg);
const { load, ScantraceError } = await import(pathToFileURL(path.join(webDir, 'scantrace.mjs')));
const started = Date.now();
const st = await load();
fs.mkdirSync(work, { recursive: true });
const course = '/work/shared/data/hw1_2024.json';

let checks = 0;
const durations = [];
function check(what, f) {
  const t0 = Date.now();
  try {
    f();
    ++checks;
    durations.push([Date.now() - t0, what]);
  } catch (e) {
    console.error(`FAIL ${what}: ${e.message.split('\n').slice(0, 8).join('\n')}`);
    process.exitCode = 1;
  }
}

function flags(o) {
  const f = [];
  if (o.shading) f.push('--shading', o.shading);
  if (o.fill_rule) f.push('--fill-rule', o.fill_rule);
  if (o.subpixel_bits !== undefined) f.push('--subpixel-bits', String(o.subpixel_bits));
  if (o.method) f.push('--method', o.method);
  return f;
}

function native(args, okStatuses = [0]) {
  const r = spawnSync(scantrace, ['-q', ...args], { encoding: 'utf8', maxBuffer: 1 << 28 });
  if (!okStatuses.includes(r.status)) throw new Error(`scantrace ${args.join(' ')}: exit ${r.status}: ${r.stderr}`);
  return r.stdout;
}

function firstDifference(a, b, width) {
  for (let i = 0; i < a.length; ++i)
    if (a[i] !== b[i]) return `first difference at pixel (${(i >> 2) % width}, ${Math.floor((i >> 2) / width)}) channel ${i & 3}: ${a[i]} vs ${b[i]}`;
  return 'none';
}

function compareRender(name, file, options) {
  check(`render ${name} ${JSON.stringify(options)}`, () => {
    const png = path.join(work, `${name}.png`);
    native(['render', file, ...flags(options), '--threads', '1', '-o', png]);
    const want = decodePng(fs.readFileSync(png));
    const got = st.render({ name: path.basename(file), data: fs.readFileSync(file) }, options);
    assert.equal(got.width, want.width);
    assert.equal(got.height, want.height);
    const same = Buffer.compare(Buffer.from(got.rgba), Buffer.from(want.rgba)) === 0;
    assert.ok(same, firstDifference(got.rgba, want.rgba, got.width));
  });
}

function readJsonl(file) {
  return fs.readFileSync(file, 'utf8').split('\n').filter((l) => l).map((l) => JSON.parse(l));
}

// Scenes: files on disk, as the CLI reads them.
const scenes = [];
if (demoScene && fs.existsSync(demoScene)) scenes.push(['demo', demoScene]);
else console.log('skipped: the built-in demo scene (no file given)');
if (fs.existsSync(course)) scenes.push(['course', course]);
else console.log(`skipped: the course scene (${course} absent)`);
const many = path.join(work, 'many_faces.json');
fs.writeFileSync(many, JSON.stringify(manyFaces(25000, 1200, 1200)));
scenes.push(['many_faces', many]);
const hard = path.join(work, 'hard_cases.json');
fs.writeFileSync(hard, JSON.stringify(hardCases()));
scenes.push(['hard_cases', hard]);

const optionSets = [
  {},
  { shading: 'flat' },
  { fill_rule: 'closed', subpixel_bits: 0 },
  { method: 'float' },
  { method: 'double', subpixel_bits: 2 },
  { method: 'halfspace' },
];
for (const [name, file] of scenes)
  for (const [i, o] of optionSets.entries())
    if (name !== 'many_faces' || i === 0) compareRender(`${name}_${i}`, file, o);

// Traces: a triangle at every level, the hard triangles, a polygon, and a scene.
const triangleCases = [
  [[20, 20], [250, 80], [300, 400]],
  [[-1e9, -1e9], [1e9, 3.5], [200.25, 1e9]],
  [[10, 500], [500, 10], [10.0001, 499.999]],
  [[100.00390625, 3.5], [7.25, 200.75], [300.5, 120.125]],
];
// Triangle 1 covers the whole canvas: at pixel level 262,144 events a trace, 13 s each here for
// nothing its scanline level does not already hold (its crossings are the 128-bit path's).
for (const [i, tri] of triangleCases.entries())
  for (const level of i === 1 ? ['triangle', 'scanline'] : ['triangle', 'scanline', 'pixel'])
    for (const o of [{}, { subpixel_bits: 0, fill_rule: 'closed', shading: 'flat' }, { method: 'float' }]) {
      check(`trace triangle ${i} ${level} ${JSON.stringify(o)}`, () => {
        const out = path.join(work, 'triangle.jsonl');
        native(['trace', '--triangle', tri.map((v) => v.join(',')).join(' '), '--level', level, ...flags(o), '-o', out]);
        assert.deepStrictEqual(st.trace({ triangle: tri }, { ...o, level }), readJsonl(out));
      });
    }
check('trace polygon', () => {
  const out = path.join(work, 'polygon.jsonl');
  const contours = [[[50, 50], [400, 60], [300, 300], [60, 420]], [[100, 100], [200, 110], [150, 200]]];
  native(['trace', '--polygon', contours.map((c) => c.map((v) => v.join(',')).join(' ')).join(' | '),
    '--colors', '1,0,0 0,1,0 0,0,1 1,1,0 0,1,1 1,0,1 0.5,0.5,0.5', '--winding', 'non-zero', '-o', out]);
  const colors = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1], [0.5, 0.5, 0.5]];
  assert.deepStrictEqual(st.trace({ polygon: contours, colors }, { winding: 'non-zero' }), readJsonl(out));
});
// The explorer's path: a trace kept in memory (keep: true) has the native trace's text, and its
// frames (frames(null, …), pixel blocks as RGBA bytes) are the frames of the trace's text with
// their PNG blocks decoded here: the same plan, the same ops, the same pixels.
check('kept trace and its frames with RGBA blocks', () => {
  const out = path.join(work, 'kept.jsonl');
  native(['trace', '--triangle', '20,20 250,80 299.5,371.25', '--shading', 'flat', '-o', out]);
  const text = st.traceText({ triangle: [[20, 20], [250, 80], [299.5, 371.25]] }, { shading: 'flat', keep: true });
  assert.deepStrictEqual(readJsonl(out), text.split('\n').filter((l) => l).map((l) => JSON.parse(l)));
  // The image the kept trace's fill drew is `scantrace render`'s of the one-face scene.
  const one = path.join(work, 'kept_triangle.json');
  fs.writeFileSync(one, JSON.stringify({ width: 512, height: 512, background: [1, 1, 1], vertices: [[20, 20], [250, 80], [299.5, 371.25]],
    vcolors: [[1, 0, 0], [0, 1, 0], [0, 0, 1]], faces: [[0, 1, 2]], depth: [0, 0, 0] }));
  native(['render', one, '--shading', 'flat', '-o', path.join(work, 'kept_triangle.png')]);
  const want = decodePng(fs.readFileSync(path.join(work, 'kept_triangle.png')));
  assert.deepStrictEqual([st.lastTraceImage.width, st.lastTraceImage.height], [want.width, want.height]);
  assert.ok(Buffer.from(st.lastTraceImage.rgba).equals(Buffer.from(want.rgba)), 'the kept trace\'s image differs from the render');
  for (const step of [0, 12, 30]) {
    const raw = st.frames(null, { first: step, count: 1, blocks: 'rgba', source: 'kept.jsonl' });
    const png = st.frames(fs.readFileSync(out, 'utf8'), { first: step, count: 1, source: 'kept.jsonl' });
    assert.deepStrictEqual(raw.steps, png.steps);
    const [a, b] = [raw.frames[0], png.frames[0]];
    assert.equal(a.ops.length, b.ops.length);
    let blocks = 0;
    a.ops.forEach((op, i) => {
      if (op[0] !== 'P') return assert.deepStrictEqual(op, b.ops[i]);
      assert.deepStrictEqual(op.slice(0, 7), b.ops[i].slice(0, 7));
      const decoded = decodePng(Buffer.from(b.ops[i][7].replace(/^data:image\/png;base64,/, ''), 'base64'));
      assert.deepStrictEqual([op[7].width, op[7].height], [decoded.width, decoded.height]);
      assert.ok(Buffer.from(op[7].data).equals(Buffer.from(decoded.rgba)), `step ${step}: block ${i}'s pixels differ`);
      ++blocks;
    });
    assert.ok(blocks > 0, `step ${step} has no pixel block`);
  }
});
// traceText's `into`: the kept image copied into the caller's array when it has the image's size
// (then lastTraceImage's rgba), a new array otherwise.
check("a kept trace's image copied into the caller's array", () => {
  const input = { triangle: [[20, 20], [250, 80], [299.5, 371.25]], width: 200, height: 150 };
  st.traceText(input, { keep: true, text: false });
  const want = st.lastTraceImage.rgba.slice();
  const into = new Uint8ClampedArray(200 * 150 * 4).fill(7);
  st.traceText({ triangle: [[1, 1], [2, 1], [1, 2]], width: 200, height: 150 }, { keep: true, text: false }); // another image first
  st.traceText(input, { keep: true, text: false }, into);
  assert.equal(st.lastTraceImage.rgba, into);
  assert.ok(Buffer.from(into).equals(Buffer.from(want)), 'the array given holds another image');
  const small = new Uint8ClampedArray(16).fill(7);
  st.traceText(input, { keep: true, text: false }, small);
  assert.notEqual(st.lastTraceImage.rgba, small);
  assert.ok(Buffer.from(st.lastTraceImage.rgba).equals(Buffer.from(want)) && small.every((v) => v === 7));
});

// The explorer's frames come as numbers (encoding: 'binary': viz::to_numbers, read back by
// scantrace.mjs's numbersFrame): every step's frame must be the frame JSON.parse gives of its
// JSON, the same ops, strings, marks, clips and numbers (lists as Float64Arrays, compared as
// arrays), and blocks of the same runs and texels; for a triangle at two sizes, a polygon with a
// hole and the demo scene.
check('frames as numbers are the frames as JSON', () => {
  const plain = (x) => {
    if (ArrayBuffer.isView(x)) return Array.from(x);
    if (Array.isArray(x)) return x.map(plain);
    if (x && typeof x === 'object' && 'texels' in x) return { width: x.width, height: x.height, cols: plain(x.cols), rows: plain(x.rows), texels: plain(x.texels) };
    if (x && typeof x === 'object') return Object.fromEntries(Object.entries(x).map(([k, v]) => [k, plain(v)]));
    return x;
  };
  const inputs = [
    [{ triangle: [[20, 20], [250, 80], [300, 400]] }, { shading: 'gouraud' }, [[688, 387], [1280, 720]]],
    [{ polygon: [[[50, 50], [400, 60], [300, 300], [60, 420]], [[100, 100], [200, 110], [150, 200]]] }, { winding: 'non-zero' }, [[960, 540]]],
    [{ scene: st.demoScene() }, { level: 'triangle' }, [[1280, 720]]],
  ];
  let frames = 0;
  for (const [input, o, sizes] of inputs) {
    st.traceText(input, { ...o, keep: true, text: false });
    for (const [width, height] of sizes)
      // The first steps (the title cards), a few scanline steps and the last (1 s for all steps).
      for (const first of [0, 1, 3, 6, 12, 20, 30, 46]) {
        const json = st.frames(null, { blocks: 'rgba', width, height, source: 'x', first, count: 1 });
        const numbers = st.frames(null, { blocks: 'rgba', encoding: 'binary', width, height, source: 'x', first, count: 1 });
        assert.deepStrictEqual(numbers.steps, json.steps);
        assert.equal(numbers.frames.length, json.frames.length);
        json.frames.forEach((f, i) => {
          assert.ok(numbers.frames[i].ops.some((op) => op[0] === 'G' && op[6] instanceof Float64Array), 'no text op read as numbers');
          assert.deepStrictEqual(plain(numbers.frames[i]), plain(f), `${JSON.stringify(input).slice(0, 40)} at ${width}x${height}, step ${first + 1}`);
          ++frames;
        });
      }
  }
  assert.ok(frames > 20, `${frames} frames compared`);
});
// A kept trace's image is made from the trace's own spans (web/bindings_trace.cpp) when the trace
// holds all of them; a trace capped by max_events (never reached here) takes the conversion of
// every pixel instead. Both must be the image the fill drew, for the methods, rules and shadings,
// a triangle cut by the canvas's edges, and polygons with a hole or crossing themselves; a
// triangle's is also render()'s of the one-face scene.
check("a kept trace's image from its spans is the fill's image", () => {
  const star = [[256, 40], [380, 440], [60, 190], [450, 190], [130, 440]];
  const holed = [[[50, 50], [400, 60], [300, 300], [60, 420]], [[100, 100], [200, 110], [150, 200]]];
  const cases = [
    ...['exact', 'float', 'double', 'halfspace'].map((method) => [{ triangle: [[20, 20], [250, 80], [299.5, 371.25]] }, { method }]),
    [{ triangle: [[20, 20], [250, 80], [299.5, 371.25]] }, { shading: 'flat', fill_rule: 'closed', subpixel_bits: 0 }],
    [{ triangle: [[-40.3, 30], [300, -20.5], [530.75, 600]], colors: [[0, 0, 0], [0.2, 0.9, 0.4], [1, 1, 0]] }, {}],
    [{ triangle: [[10, 10], [200, 15], [60, 120]], width: 300, height: 200 }, { shading: 'flat' }],
    [{ polygon: [star] }, { winding: 'even-odd' }],
    [{ polygon: [star] }, { winding: 'non-zero', shading: 'flat' }],
    [{ polygon: holed }, { winding: 'non-zero' }],
  ];
  for (const [input, options] of cases) {
    const what = JSON.stringify([input, options]);
    st.traceText(input, { ...options, keep: true, text: false });
    const fromSpans = st.lastTraceImage;
    st.traceText(input, { ...options, keep: true, text: false, max_events: 1e9 });
    const everyPixel = st.lastTraceImage;
    assert.deepStrictEqual([fromSpans.width, fromSpans.height], [everyPixel.width, everyPixel.height], what);
    assert.ok(Buffer.from(fromSpans.rgba).equals(Buffer.from(everyPixel.rgba)), `${what}: the image from the spans differs`);
    assert.ok(fromSpans.rgba.some((v, i) => i % 4 !== 3 && v !== 255), `${what}: nothing filled`);
    if (input.triangle) {
      const [w, h] = [input.width || 512, input.height || 512];
      const scene = { width: w, height: h, background: [1, 1, 1], vertices: input.triangle,
        vcolors: input.colors || [[1, 0, 0], [0, 1, 0], [0, 0, 1]], faces: [[0, 1, 2]], depth: [0, 0, 0] };
      assert.ok(Buffer.from(fromSpans.rgba).equals(Buffer.from(st.render(scene, options).rgba)), `${what}: differs from render()`);
    }
  }
});
// A kept trace's image is drawn on a canvas the module keeps from call to call
// (web/traced_image.hpp), put back to the background only where the last fill wrote. Every image
// of a drag (a vertex moved a little at a time, rows gained and lost; then far, the triangle turned
// over and cut by the canvas's edges), with the method, level, size and input switched between
// moves and calls that fail in between, must be the image of that input traced alone: traced by
// another module right after an input of another size, which clears its whole canvas.
const reference = await load();
check("kept traces one after another: each image the input's alone", () => {
  const star = [[256, 40], [380, 440], [60, 190], [450, 190], [130, 440]];
  const moved = (i, far = 1) => {
    const k = far * 27 * (1 - Math.cos(i * 0.1));
    return { triangle: [[20, 20], [250, 80], [300 - k, 400 - 0.6 * k]] };
  };
  const calls = [];
  for (let i = 1; i <= 40; ++i) calls.push([moved(i), { shading: 'gouraud' }]);
  for (let i = 1; i <= 6; ++i) calls.push([moved(5 * i, 12), { shading: 'flat' }]);
  calls.push([moved(3), { method: 'halfspace' }], [moved(4), {}], [moved(5), { level: 'triangle' }], [moved(6), {}]);
  calls.push([{ ...moved(7), width: 300, height: 200 }, {}], [moved(8), {}], [{ polygon: [star] }, { winding: 'non-zero' }], [moved(9), {}]);
  calls.push(['bad', {}], [moved(10), {}], [{ triangle: [[20, 20], [250, 80], [NaN, 400]] }, {}], [moved(11), { method: 'float' }]);
  let compared = 0;
  for (const [input, options] of calls) {
    const what = JSON.stringify([input, options]);
    const o = { ...options, keep: true, text: false };
    if (input === 'bad') {
      assert.throws(() => st.traceText({ triangle: [[0, 0], [1, 1]] }, o), ScantraceError);
      continue;
    }
    let image;
    try {
      st.traceText(input, o);
      image = st.lastTraceImage;
    } catch (e) {
      // The input the module refuses must be refused alone too.
      assert.throws(() => reference.traceText(input, o), ScantraceError, what);
      continue;
    }
    reference.traceText({ triangle: [[0, 0], [2, 0], [0, 2]], width: 3, height: 3 }, { keep: true, text: false });
    reference.traceText(input, o);
    const alone = reference.lastTraceImage;
    assert.deepStrictEqual([image.width, image.height], [alone.width, alone.height], what);
    assert.ok(Buffer.from(image.rgba).equals(Buffer.from(alone.rgba)), `${what}: the image differs from the input's traced alone`);
    ++compared;
  }
  assert.ok(compared >= 50, `${compared} images compared`);
});
// The course scene's first 300 faces (its whole trace is 49 MB, a minute to decode twice here).
for (const [name, file] of scenes.filter(([n]) => n !== 'many_faces'))
  check(`trace scene ${name}`, () => {
    const out = path.join(work, `${name}.jsonl`);
    const some = name === 'course' ? { triangles: [...Array(300).keys()] } : {};
    native(['trace', file, ...(some.triangles ? ['--triangles', '0-299'] : []), '-o', out]);
    assert.deepStrictEqual(st.trace({ scene: { name: path.basename(file), data: fs.readFileSync(file) } }, some), readJsonl(out));
  });

// why: pixels of each scene (an edge, the middle, a corner), as a document and as text.
for (const [name, file] of scenes.filter(([n]) => n !== 'many_faces'))
  for (const [x, y] of [[0, 0], [200, 200], [256, 300], [511, 511]])
    check(`why ${name} ${x} ${y}`, () => {
      const want = JSON.parse(native(['why', file, String(x), String(y), '--json']));
      assert.deepStrictEqual(st.why({ name: path.basename(file), data: fs.readFileSync(file) }, x, y), want);
      // The text the explorer shows: the command's own, without --json.
      assert.strictEqual(st.lastWhyText, native(['why', file, String(x), String(y)]));
    });

// diff: a student-style image of each scene (the render with the closed rule and whole pixels,
// flipped colours of a block, a missing corner), through the native CLI and the module.
for (const [name, file] of scenes.filter(([n]) => n !== 'many_faces'))
  check(`diff ${name}`, () => {
    const png = path.join(work, `${name}_student.png`);
    native(['render', file, '--fill-rule', 'closed', '--subpixel-bits', '0', '-o', png]);
    const img = decodePng(fs.readFileSync(png));
    for (let y = 10; y < 40; ++y)
      for (let x = 10; x < 60; ++x) img.rgba[(y * img.width + x) * 4] ^= 0x80;
    fs.writeFileSync(png, encodePng(img));
    const want = JSON.parse(native(['diff', file, png, '--json'], [0, 3]));
    const got = st.diff({ name: path.basename(file), data: fs.readFileSync(file) }, { ...img, name: png });
    assert.deepStrictEqual(got, want);
  });

// Bad input: the CLI's one-line message, and the module keeps working.
check('bad scene', () => {
  const bad = path.join(work, 'bad.json');
  fs.writeFileSync(bad, '{"width": 10, "height": 10, "vertices": [[0, 0]], "faces": [[0, 1, 2]]}');
  const r = spawnSync(scantrace, ['render', 'bad.json', '-o', 'bad.png'], { encoding: 'utf8', cwd: work });
  assert.equal(r.status, 1);
  assert.throws(() => st.render({ name: 'bad.json', data: fs.readFileSync(bad) }), (e) => {
    assert.ok(e instanceof ScantraceError);
    assert.equal(e.status, 1);
    assert.ok(r.stderr.includes(e.message), `CLI said ${JSON.stringify(r.stderr)}, module ${JSON.stringify(e.message)}`);
    return true;
  });
  assert.equal(st.render(fs.readFileSync(hard, 'utf8')).width, 512);
});

durations.sort((x, y) => y[0] - x[0]);
console.log(`slowest: ${durations.slice(0, 5).map(([ms, what]) => `${what} ${(ms / 1000).toFixed(1)} s`).join('; ')}`);
console.log(`${checks} checks passed${process.exitCode ? ', some FAILED' : ''} in ${((Date.now() - started) / 1000).toFixed(1)} s`);
