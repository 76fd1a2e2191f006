// Assembles the web build's pages (docs/web.md), each one self-contained HTML file: a module's
// glue, its JavaScript API, the page's script and the .wasm (gzip, base64; the page inflates it
// with the browser's DecompressionStream) inlined into the page's template. The explorer carries
// the full module (scantrace_wasm), the trace page its own smaller one (scantrace_player). No
// network, no external font or script: they work opened from file://.
//
//   node make_page.mjs explorer BUILD_WEB_DIR OUT.html    the explorer
//   node make_page.mjs player BUILD_WEB_DIR OUT.html      the trace page's template: `replay -o
//        OUT.html` (cli/trace_page.cpp) puts {cfg, trace (gzip, base64)} in place of
//        /*SCANTRACE_PAGE_DATA*/null
import fs from 'node:fs';
import path from 'node:path';
import { execFileSync } from 'node:child_process';

const here = path.dirname(new URL(import.meta.url).pathname);
const [kind, dir, out] = process.argv.slice(2);
const read = (p) => fs.readFileSync(p, 'utf8');

// The modules become one script: their imports of each other dropped, their exports plain.
const unmodule = (text) =>
  text
    .replace(/^import [^;]*from '\.\.?\/[\w./]+';$/gm, '')
    .replace(/^export default \w+;$/gm, '')
    .replace(/^export (class|async function|function|const) /gm, '$1 ');

// The trace page's own scripts without their whole-line comments and indentation, which are for
// their readers (a tenth of the course triangle's page, whose goal is 400 KB); none of these
// files has a string running over lines, nor ' // ' inside a string.
// A comment after code goes too where no quote comes before it; blank lines go.
const uncommented = (text) => text.replace(/^[ \t]*\/\/.*\n/gm, '').replace(/^[ \t]+/gm, '')
  .replace(/^([^'"`\n]*?[;,{}()\]])[ \t]+\/\/ .*$/gm, '$1').replace(/\n\n+/g, '\n');

// A module's .wasm as the page holds it: gzip, base64. Compressed by libdeflate's level 12
// (SCANTRACE_LIBDEFLATE_GZIP, found by web/CMakeLists.txt; libdeflate-gzip on the PATH when run by
// hand), 5 % smaller than zlib's level 9: the trace page's goal is 400 KB.
const gzipTool = process.env.SCANTRACE_LIBDEFLATE_GZIP || 'libdeflate-gzip';
const inlined = (name) =>
  execFileSync(gzipTool, ['-12', '-c', path.join(dir, name)], { maxBuffer: 1 << 28 }).toString('base64');
const helpers = `async function gunzipBase64(text) {
  // A plain loop: Uint8Array.from(atob(text), callback) calls a function per byte.
  const chars = atob(text);
  const bytes = new Uint8Array(chars.length);
  for (let i = 0; i < chars.length; ++i) bytes[i] = chars.charCodeAt(i);
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}
// Where the opening time goes (docs/performance.md; web/bench/explorer_drag.mjs reads them):
// milliseconds from navigation start, kept on the body.
function openMark(name) {
  document.body.dataset[name + 'Ms'] = performance.now().toFixed(0);
}
function showFatal(e) {
  const el = document.getElementById('error');
  el.hidden = false;
  el.textContent = 'error: ' + (e && e.message ? e.message : e);
}`;
// The explorer's modules (web/explorer/), in an order where each follows those it imports.
const explorerModules = ['state.js', 'answers.js', 'controls.js', 'view.js', 'controller.js', 'explorer.js'];
// The player core's modules, each after those it imports.
const playerCore = ['keys.mjs', 'controller.mjs', 'bind.mjs'];
// The players' key table (player/keys.json) as the script's SCANTRACE_KEYS, without its note.
// The trace page's holds only its own actions (a few hundred bytes of its 400 KB goal).
const keyTableOf = (page) => {
  const table = JSON.parse(read(path.join(here, 'player', 'keys.json')));
  if (page) table.actions = table.actions.filter((a) => a.in.includes(page)).map((a) => ({ ...a, in: [page] }));
  return `const SCANTRACE_KEYS = ${JSON.stringify(table, (k, v) => (k === 'about' ? undefined : v))};`;
};
let script;
if (kind === 'explorer') {
  // The full module (scantrace_wasm) and the JavaScript API.
  script = [
    unmodule(read(path.join(dir, 'scantrace_wasm.mjs'))),
    unmodule(read(path.join(here, 'scantrace.mjs'))),
    helpers,
    // The key table and its reader (player/keys.mjs), shared with every player, then the
    // explorer's modules, each after those it imports.
    keyTableOf(null),
    unmodule(read(path.join(here, 'player', 'keys.mjs'))),
    ...explorerModules.map((m) => unmodule(read(path.join(here, 'explorer', m)))),
    `openMark('script');
gunzipBase64('${inlined('scantrace_wasm.wasm')}')
  .then((wasmBinary) => { openMark('inflated'); return load({ wasmBinary }); })
  .then((st) => { openMark('loaded'); return start(st); })
  .catch(showFatal);`,
  ];
} else if (kind === 'player') {
  // The trace page's own module (scantrace_player: player/player_module.cpp), a third of the
  // full one's size, gzipped (docs/performance.md).
  script = [
    unmodule(read(path.join(dir, 'scantrace_player.mjs'))),
    uncommented(unmodule(read(path.join(here, 'player', 'player_api.mjs')))),
    uncommented(helpers),
    // The canvas drawer and the player core (keys.json, keys.mjs, controller.mjs, bind.mjs) the
    // step page embeds too (cmake/web_player.cmake), then the trace page's own script.
    uncommented(read(path.join(here, 'player', 'frame_draw.js'))),
    keyTableOf('trace'),
    ...[...playerCore, 'player.js'].map((m) => uncommented(unmodule(read(path.join(here, 'player', m))))),
    'const page = /*SCANTRACE_PAGE_DATA*/null;',
    `Promise.all([gunzipBase64('${inlined('scantrace_player.wasm')}'), gunzipBase64(page.trace)])
  .then(([wasmBinary, trace]) => loadPlayer(wasmBinary).then((pm) => startPlayer(pm, page.cfg, new TextDecoder().decode(trace))))
  .catch(showFatal);`,
  ];
} else {
  console.error('usage: node make_page.mjs explorer|player BUILD_WEB_DIR OUT.html');
  process.exit(2);
}
// The head both pages share (doctype, charset, viewport), then the page's own template.
// The trace page's template without its indentation (it holds no <pre>).
const own = read(path.join(here, kind, `${kind}.html`)).replace(/^<!--.*-->\n/, '');
const template = read(path.join(here, 'page_head.html')) + (kind === 'player' ? own.replace(/^[ \t]+/gm, '') : own);
const page = template.replace('/*SCANTRACE_SCRIPT*/', () => script.join('\n'));
// Written whole under another name, then renamed: never half a page.
fs.writeFileSync(out + '.tmp', page);
fs.renameSync(out + '.tmp', out);
console.log(`${out}: ${(page.length / 1e6).toFixed(2)} MB`);
