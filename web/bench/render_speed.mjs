// The WebAssembly build's speed against the native command (docs/performance.md, "In the
// browser"): the fill's own time (the module's render() times the same render() call the
// command times; scene loading excluded on both sides), alternated run by run, medians; and the
// explorer's work when a vertex of the course triangle is dragged (trace + the current step's
// frame), in Node.
//
//   node render_speed.mjs BUILD_WEB_DIR SCANTRACE SCENE.json [RUNS]
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const [webDir, scantrace, scene, runsArg] = process.argv.slice(2);
const runs = Number(runsArg || 21);
const { load } = await import(pathToFileURL(path.join(webDir, 'scantrace.mjs')));
const st = await load();
const data = fs.readFileSync(scene);
const median = (v) => [...v].sort((a, b) => a - b)[v.length >> 1];

const wasm = [], native = [];
for (let i = 0; i < runs; ++i) {
  wasm.push(st.render({ name: path.basename(scene), data }, {}).ms);
  // `scantrace render` logs "... in X ms (loaded in Y ms)": X is the render alone.
  const r = spawnSync(scantrace, ['render', scene, '--threads', '1', '-o', '/tmp/scantrace-render-speed.png'], { encoding: 'utf8' });
  const m = / ([\d.]+) ms(?:,| \()/.exec(r.stderr);
  if (!m) throw new Error(`cannot read the render time in: ${r.stderr}`);
  native.push(Number(m[1]));
}
console.log(`render ${path.basename(scene)}: wasm median ${median(wasm).toFixed(2)} ms, native median ${median(native).toFixed(2)} ms, ratio ${(median(wasm) / median(native)).toFixed(2)} (${runs} runs each, alternated)`);

// The explorer's work on a drag: trace the moved triangle, then compose the current step's frame.
const drag = [];
for (let i = 0; i < runs; ++i) {
  const t0 = performance.now();
  const text = st.traceText({ triangle: [[20, 20], [250, 80], [300 - i, 400]] }, { level: 'scanline' });
  st.frames(text, { first: 12, count: 1 });
  drag.push(performance.now() - t0);
}
console.log(`drag of the course triangle (trace + step 13's frame): median ${median(drag).toFixed(2)} ms`);
