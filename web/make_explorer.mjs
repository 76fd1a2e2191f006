// Assembles the explorer (docs/web.md): one self-contained HTML file, the module's glue, the
// JavaScript API, the page's script and the .wasm (base64) inlined into explorer/explorer.html.
// No network, no external font or script: it works opened from file://.
//
//   node make_explorer.mjs BUILD_WEB_DIR OUT.html
import fs from 'node:fs';
import path from 'node:path';

const here = path.dirname(new URL(import.meta.url).pathname);
const [dir, out] = process.argv.slice(2);
const read = (p) => fs.readFileSync(p, 'utf8');

// The modules become one script: their imports of each other dropped, their exports plain.
const unmodule = (text) =>
  text
    .replace(/^import [^;]*from '\.\/[\w.]+';$/gm, '')
    .replace(/^export default \w+;$/gm, '')
    .replace(/^export (class|async function|function|const) /gm, '$1 ');

const wasm = fs.readFileSync(path.join(dir, 'scantrace_wasm.wasm')).toString('base64');
const script = [
  unmodule(read(path.join(dir, 'scantrace_wasm.mjs'))),
  unmodule(read(path.join(here, 'scantrace.mjs'))),
  unmodule(read(path.join(here, 'explorer', 'state.js'))),
  unmodule(read(path.join(here, 'explorer', 'explorer.js'))),
  `const wasmBinary = Uint8Array.from(atob('${wasm}'), (c) => c.charCodeAt(0));`,
  'load({ wasmBinary }).then(start).catch((e) => { const el = document.getElementById("error"); el.hidden = false; el.textContent = "error: " + e.message; });',
].join('\n');
const page = read(path.join(here, 'explorer', 'explorer.html')).replace('/*SCANTRACE_SCRIPT*/', () => script);
// Written whole under another name, then renamed: never half a page.
fs.writeFileSync(out + '.tmp', page);
fs.renameSync(out + '.tmp', out);
console.log(`${out}: ${(page.length / 1e6).toFixed(2)} MB`);
