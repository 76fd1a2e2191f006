// The option names of the JavaScript API: scantrace.d.ts lists, for each option, exactly the names
// the native command offers (its --help, built from the option tables of src/option_table.hpp);
// the module takes each of them, and a trace it records says it in its header as the command's
// trace does; anything else is the module's "unknown value" error.
//
//   node node_options.mjs WEB_DIR SCANTRACE WORK_DIR DEMO_SCENE.json
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

import { check, summary } from './check.mjs';

const [webDir, scantraceArg, work] = process.argv.slice(2);
const scantrace = path.resolve(scantraceArg);
const { load, ScantraceError } = await import(pathToFileURL(path.join(webDir, 'scantrace.mjs')));
const st = await load();
fs.mkdirSync(work, { recursive: true });

// The API's key, the command's flag and the trace header's key (null: not in a header).
const OPTIONS = [
  ['shading', '--shading', 'shading'],
  ['fill_rule', '--fill-rule', 'fill_rule'],
  ['method', '--method', null],
  ['winding', '--winding', 'winding_rule'],
  ['cull', '--cull', 'cull'],
  ['depth', '--depth', 'visibility'],
  ['level', '--level', 'level'],
];

// `key?: 'a' | 'b';` of scantrace.d.ts, as a list of names.
const dts = fs.readFileSync(path.join(path.dirname(fileURLToPath(import.meta.url)), '..', 'scantrace.d.ts'), 'utf8');
function typed(key) {
  const m = dts.match(new RegExp(`\\b${key}\\?: ((?:'[^']*'(?: \\| )?)+);`));
  assert.ok(m, `scantrace.d.ts has no ${key}`);
  return [...m[1].matchAll(/'([^']*)'/g)].map((x) => x[1]);
}

// The choices `scantrace trace --help` gives `flag`: "{a,b,c}".
const help = spawnSync(scantrace, ['trace', '--help'], { encoding: 'utf8' }).stdout;
function offered(flag) {
  const m = help.match(new RegExp(`^\\s*${flag} TEXT:\\{([^}]*)\\}`, 'm'));
  assert.ok(m, `trace --help has no ${flag} TEXT:{…}`);
  return m[1].split(',');
}

const triangle = { triangle: [[1, 1], [9, 2], [4, 8]], width: 12, height: 12 };
const polygon = { polygon: [[[1, 1], [9, 2], [4, 8]]], width: 12, height: 12 };

for (const [key, flag, headerKey] of OPTIONS) {
  check(`${key}: scantrace.d.ts lists the command's ${flag} names`, () => {
    assert.deepEqual(typed(key), offered(flag));
  });
  check(`${key}: the module takes each name, and says it in the trace's header`, () => {
    for (const name of typed(key)) {
      const text = st.traceText(key === 'winding' ? polygon : triangle, { [key]: name });
      const header = JSON.parse(text.split('\n')[0]);
      if (headerKey) {
        const absent = { visibility: 'painter', cull: 'none' }[headerKey];
        assert.equal(header[headerKey] ?? absent, name);
      }
    }
  });
  check(`${key}: anything else is an unknown value`, () => {
    assert.throws(() => st.traceText(triangle, { [key]: 'bogus' }), (e) => {
      assert.ok(e instanceof ScantraceError);
      assert.match(e.message, key === 'level' ? /unknown trace level "bogus"/ : new RegExp(`options\\.${key}: unknown value "bogus"`));
      return true;
    });
  });
}

console.log(summary());
