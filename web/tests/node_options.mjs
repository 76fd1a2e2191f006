// The option names of the JavaScript API: the module's optionTable() lists, for each option,
// exactly the names the native command offers (its --help, built from the option tables of
// src/option_table.hpp) and the command's default; the module takes each of them, and a trace it
// records says it in its header as the command's trace does; anything else is the module's
// "unknown value" error. scantrace.d.ts types them as strings and names no value.
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

// The API's key, the command's flag, the option's table (optionTable()'s key) and the trace
// header's key (null: not in a header).
const OPTIONS = [
  ['shading', '--shading', 'shading', 'shading'],
  ['fill_rule', '--fill-rule', 'fill_rule', 'fill_rule'],
  ['method', '--method', 'method', null],
  ['winding', '--winding', 'winding_rule', 'winding_rule'],
  ['cull', '--cull', 'cull', 'cull'],
  ['depth', '--depth', 'visibility', 'visibility'],
  ['level', '--level', 'level', 'level'],
];

const table = st.optionTable();
const dts = fs.readFileSync(path.join(path.dirname(fileURLToPath(import.meta.url)), '..', 'scantrace.d.ts'), 'utf8');

// The choices `scantrace trace --help` gives `flag`, "{a,b,c}", and its default ("=b"), if any.
const help = spawnSync(scantrace, ['trace', '--help'], { encoding: 'utf8' }).stdout;
function offered(flag) {
  const m = help.match(new RegExp(`^\\s*${flag} TEXT:\\{([^}]*)\\}(?:=(\\S+))?`, 'm'));
  assert.ok(m, `trace --help has no ${flag} TEXT:{…}`);
  return { names: m[1].split(','), fallback: m[2] ?? null };
}

const triangle = { triangle: [[1, 1], [9, 2], [4, 8]], width: 12, height: 12 };
const polygon = { polygon: [[[1, 1], [9, 2], [4, 8]]], width: 12, height: 12 };

check('optionTable() has the tables of the options above, and nothing else', () => {
  assert.deepEqual(Object.keys(table).sort(), [...OPTIONS.map((o) => o[2]), 'occlusion'].sort());
});

for (const [key, flag, tableKey, headerKey] of OPTIONS) {
  check(`${key}: optionTable().${tableKey} lists the command's ${flag} names and default`, () => {
    const { names, fallback } = offered(flag);
    assert.deepEqual(table[tableKey].names, names);
    // --cull and --depth show no default: theirs depends on the input (a model or a scene).
    if (fallback !== null) assert.equal(table[tableKey].default, fallback);
    else assert.ok(names.includes(table[tableKey].default));
  });
  check(`${key}: scantrace.d.ts types it as a string, naming none of its values`, () => {
    assert.match(dts, new RegExp(`\\b${key}\\?: string;`));
    for (const name of table[tableKey].names) assert.ok(!dts.includes(`'${name}'`), `scantrace.d.ts spells '${name}'`);
  });
  check(`${key}: the module takes each name, and says it in the trace's header`, () => {
    for (const name of table[tableKey].names) {
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

// The explorer's address (web/explorer/state.js): each of the four options it keeps takes each
// name the command offers, and a missing or unknown one is the command's default.
// The explorer's modules see the key table as the page's global (make_page.mjs defines it).
const here = path.dirname(fileURLToPath(import.meta.url));
globalThis.SCANTRACE_KEYS = JSON.parse(fs.readFileSync(path.join(here, '..', 'player', 'keys.json'), 'utf8'));
const { fromHash, namedOptions } = await import('../explorer/state.js');
const explorerFlags = { shading: '--shading', fill_rule: '--fill-rule', method: '--method', winding: '--winding' };
check("the explorer's address takes exactly the command's names, and defaults to the command's", () => {
  assert.deepEqual(Object.keys(namedOptions).sort(), Object.keys(explorerFlags).sort());
  for (const [key, flag] of Object.entries(explorerFlags)) {
    const { names, fallback } = offered(flag);
    for (const name of names) assert.equal(fromHash(`#${key}=${name}`, table)[key], name);
    assert.equal(fromHash(`#${key}=bogus`, table)[key], fallback);
    assert.equal(fromHash('#', table)[key], fallback);
  }
});

console.log(summary());
