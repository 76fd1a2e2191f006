// scantrace's JavaScript API (docs/web.md; types in scantrace.d.ts): the real fill, trace, frame
// composer, why and diff, compiled to WebAssembly (scantrace_wasm.mjs + .wasm), in Node and in a
// page alike.
//
//   import { load } from './scantrace.mjs';
//   const st = await load();
//   const { width, height, rgba } = st.render(sceneJsonText);
//
// Inputs are handed to the module as files in its memory file system, under the name the caller
// gives (default scene.json), so messages name them as the CLI names its files.
import createScantraceWasm from './scantrace_wasm.mjs';

export class ScantraceError extends Error {
  // status 1: bad input (the message is the CLI's one line); 2: a bad argument of the API.
  constructor(message, status) {
    super(message);
    this.name = 'ScantraceError';
    this.status = status;
  }
}

const isNode = typeof process === 'object' && !!(process.versions && process.versions.node);

async function wasmBytes() {
  const url = new URL('./scantrace_wasm.wasm', import.meta.url);
  if (isNode) {
    const fs = await import('node:fs/promises');
    return new Uint8Array(await fs.readFile(url));
  }
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: ${response.status} ${response.statusText}`);
  return new Uint8Array(await response.arrayBuffer());
}

// options.wasmBinary: the module's bytes (a page with the wasm inlined); else read beside this file.
export async function load(options = {}) {
  const wasmBinary = options.wasmBinary || (await wasmBytes());
  const printErr = options.printErr || (() => {});
  const module = await createScantraceWasm({ wasmBinary, print: options.print || (() => {}), printErr });
  return new Scantrace(module, printErr);
}

// The checks the command makes of its arguments, made here before anything reaches the module
// (which makes them again: web/bindings*.cpp), with the command's words: a value
// is never truncated into another one (`x | 0` made 2**32 + 100 pixel 100, NaN and "abc" pixel 0).
function pixelCoordinate(v, axis) {
  // `scantrace why`'s X and Y: an int, 0 or more (from_chars into an int).
  if (typeof v !== 'number' || !Number.isInteger(v) || v < 0 || v > 2147483647)
    throw new ScantraceError(`${axis}: must be a pixel ${axis === 'X' ? 'column, 0 to the canvas width' : 'row, 0 to the canvas height'} - 1 (got "${String(v)}")`, 2);
  return v;
}

function checkOptions(options) {
  if (options === null || typeof options !== 'object' || Array.isArray(options))
    throw new ScantraceError('options: not an object', 2);
  if ('tolerance' in options) {
    // `diff --tolerance`: a number from 0 to 1 (its range checked first, as CLI11 checks it: an
    // infinity is out of range), finite (NaN passed every image, and JSON makes it null).
    const t = options.tolerance;
    if (typeof t === 'number' && (t < 0 || t > 1))
      throw new ScantraceError(`tolerance: Value ${t} not in range 0.000000 to 1.000000`, 2);
    if (typeof t !== 'number' || !Number.isFinite(t))
      throw new ScantraceError(`tolerance: "${String(t)}" is not a finite number`, 2);
  }
  if ('max_bytes' in options) {
    // `trace --max-bytes`: an integer, 1024 to 2^50.
    const b = options.max_bytes;
    if (typeof b !== 'number' || !Number.isInteger(b) || b < 1024 || b > 2 ** 50)
      throw new ScantraceError(`max_bytes: Value ${String(b)} not in range 1024 to 1125899906842624`, 2);
  }
  for (const key of ['first', 'count', 'rows_per_step', 'width', 'height', 'subpixel_bits', 'max_events']) {
    // Counts and sizes: the module reads them as integers, which 1.5 or -1 would not be.
    const v = options[key];
    if (key in options && (typeof v !== 'number' || !Number.isInteger(v) || v < 0))
      throw new ScantraceError(`${key}: must be an integer 0 or more (got "${String(v)}")`, 2);
  }
  return JSON.stringify(options);
}

// The last part of a file's name, as the module's file system takes it (`fallback` for none): '.'
// and '..' name no file (they threw emscripten's plain "FS error").
function baseName(name, fallback, what) {
  const base = String(name).replace(/^.*[\\/]/, '') || fallback;
  if (base === '.' || base === '..' || base.includes('\0'))
    throw new ScantraceError(`${what}: "${String(name)}" is not a file name`, 2);
  return base;
}

// Any other error of a call (a file the module's file system refuses, a wrong type of argument,
// a string too long for the engine) as a ScantraceError: status 2 for an argument, else 1.
function asScantraceError(e) {
  if (e instanceof ScantraceError) return e;
  const fsError = e && typeof e.errno === 'number';
  const message = fsError ? `the module's file system refused the file (errno ${e.errno})` : String((e && e.message) || e);
  return new ScantraceError(message, e instanceof TypeError || fsError ? 2 : 1);
}

const decoder = new TextDecoder();

// A pixel block `w` × `h` from its runs ({at, cols, rows}: run widths and heights) and its texels
// (RGBA, one per run pair, row by row, from byte `at` of `bytes`): {width, height, cols, rows,
// texels}, which drawScantraceFrame draws as it is (viz/frame_json.cpp), and `data`, the block's
// RGBA bytes, expanded when first read.
function runsBlock(w, h, { at, cols, rows }, bytes) {
  const texels = bytes.subarray(at, at + cols.length * rows.length * 4);
  let data = null;
  return {
    width: w, height: h, cols, rows, texels,
    get data() {
      if (data) return data;
      data = new Uint8ClampedArray(w * h * 4);
      const out = new Uint32Array(data.buffer), from = new Uint32Array(texels.slice().buffer);
      for (let r = 0, y = 0; r < rows.length; y += rows[r++]) {
        // The run's first row from its texels, the others copies of it.
        for (let c = 0, i = y * w; c < cols.length; ++c) for (let k = cols[c], v = from[r * cols.length + c]; k > 0; --k) out[i++] = v;
        for (let k = 1; k < rows[r]; ++k) out.copyWithin((y + k) * w, y * w, (y + 1) * w);
      }
      return data;
    },
  };
}

// A frame written as numbers (frames' encoding: 'binary'; viz/frame_json.hpp's to_numbers):
// head {w, h, bg, at, n, strings, marks}, its numbers the n doubles from byte `at` of `bytes`
// (the texels of its blocks are in the same bytes). Gives the frame JSON.parse would give of its
// JSON (tests/node_compare.mjs holds them equal), each list of numbers of its text ops, glyphs and
// blocks a Float64Array over the bytes: no number is written as text or parsed back.
const opKinds = ['R', 'L', 'C', 'G', 'P'];
function numbersFrame(head, bytes) {
  const v = new Float64Array(bytes.buffer, bytes.byteOffset + head.at, head.n), s = head.strings;
  let i = 0;
  const list = (n) => v.subarray(i, (i += n));
  const ops = new Array(v[i++]);
  for (let k = 0; k < ops.length; ++k) {
    const kind = opKinds[v[i++]];
    // Read number by number: Array.from of a subarray, and destructuring one (its iterator), were
    // most of this function's time (docs/performance.md, "Ninth round").
    const clip = v[i++] ? [v[i++], v[i++], v[i++], v[i++]] : null;
    const mark = v[i++];
    const op = [kind, clip, mark < 0 ? null : head.marks[mark]];
    if (kind === 'R' || kind === 'L') op.push(v[i++], v[i++], v[i++], v[i++], s[v[i++]], v[i++]);
    else if (kind === 'C') op.push(v[i++], v[i++], v[i++], s[v[i++]], v[i++]);
    else if (kind === 'G') op.push(s[v[i++]], s[v[i++]], v[i++], list(3 * v[i++]));
    else {
      const x = v[i++], y = v[i++], w = v[i++], h = v[i++], at = v[i++];
      const cols = list(v[i++]), rows = list(v[i++]);
      op.push(x, y, w, h, runsBlock(w, h, { at, cols, rows }, bytes));
    }
    ops[k] = op;
  }
  const glyphs = new Array(v[i++]);
  for (let g = 0; g < glyphs.length; ++g) {
    const strokes = (glyphs[g] = new Array(v[i++]));
    for (let k = 0; k < strokes.length; ++k) strokes[k] = list(v[i++]);
  }
  return { w: head.w, h: head.h, bg: head.bg, ops, glyphs };
}

export class Scantrace {
  constructor(module, printErr = () => {}) {
    this.m = module;
    this.printErr = printErr;
    // The warning of the last call (a trace its byte cap cut: the command's line), or null.
    this.lastWarning = null;
    // The command's text of the last why's story (why()), or null.
    this.lastWhyText = null;
    this._options = null; // optionTable()'s JSON, read once
    // Inputs are written to /in and named relative to it, so a message names the file as the
    // caller named it ("scene.json: …"), as the CLI names a file given relative to its directory.
    this.m.FS.mkdirTree('/in');
    this.m.FS.chdir('/in');
  }

  // scene: JSON text, a scene object, or {name, data} (data text or bytes; name ending .obj: a model).
  _sceneFile(scene) {
    let name = 'scene.json';
    let data = scene;
    if (scene && typeof scene === 'object' && !(scene instanceof Uint8Array)) {
      if ('data' in scene && 'name' in scene) {
        name = String(scene.name);
        data = scene.data;
      } else {
        data = JSON.stringify(scene);
      }
    }
    if (typeof data !== 'string' && !(data instanceof Uint8Array))
      throw new ScantraceError('scene: JSON text, a scene object or {name, data}', 2);
    const base = baseName(name, 'scene.json', 'scene');
    this.m.FS.writeFile(`/in/${base}`, data);
    return base;
  }

  _call(name, args) {
    const m = this.m;
    const stack = [];
    const cargs = args.map((a) => {
      if (typeof a === 'string') {
        const n = m.lengthBytesUTF8(a) + 1;
        const p = m._malloc(n);
        m.stringToUTF8(a, p, n);
        stack.push(p);
        return p;
      }
      if (a instanceof Uint8Array) {
        const p = m._malloc(Math.max(1, a.length));
        m.HEAPU8.set(a, p);
        stack.push(p);
        return p;
      }
      return a;
    });
    let status;
    try {
      status = m['_st_' + name](...cargs);
    } finally {
      for (const p of stack) m._free(p);
    }
    if (status !== 0) throw new ScantraceError(m.UTF8ToString(m._st_error()), status);
    this.lastWarning = m.UTF8ToString(m._st_warning()) || null;
    if (this.lastWarning) this.printErr(this.lastWarning);
    return {
      text: () => decoder.decode(m.HEAPU8.subarray(m._st_result_text(), m._st_result_text() + m._st_result_size())),
      bytes: () => m.HEAPU8.slice(m._st_result_bytes(), m._st_result_bytes() + m._st_result_bytes_size()),
      // The bytes copied into `target` (a Uint8ClampedArray of their length): true, else false.
      bytesInto: (target) => {
        const at = m._st_result_bytes(), n = m._st_result_bytes_size();
        if (!target || target.length !== n) return false;
        target.set(m.HEAPU8.subarray(at, at + n));
        return true;
      },
    };
  }

  // {width, height, rgba (Uint8ClampedArray, row-major RGBA), faces, ms}: `scantrace render`'s image.
  render(scene, options = {}) {
    const r = this._call('render', [this._sceneFile(scene), checkOptions(options)]);
    const info = JSON.parse(r.text());
    return { ...info, rgba: new Uint8ClampedArray(r.bytes().buffer) };
  }

  // The JSON Lines `scantrace trace` writes, as text. input: {scene} | {triangle, colors?,
  // width?, height?} | {polygon, colors?, width?, height?}.
  // With options.keep, lastTraceImage is the image the traced fill drew, {width, height, rgba};
  // with keep and text: false, the trace is kept but no text written ('' returned). `into`: an
  // ImageData (or Uint8ClampedArray) that takes the image's bytes when it has their size, and is
  // then lastTraceImage's rgba (a drag's moves reuse one: a new 1 MB array and ImageData a move
  // cost 0.7 ms more in Chromium).
  traceText(input, options = {}, into = null) {
    const spec = { ...input };
    if ('scene' in spec) spec.scene = this._sceneFile(spec.scene);
    const r = this._call('trace', [JSON.stringify(spec), checkOptions(options)]);
    if (options.keep) {
      const target = into && (into.data || into);
      const rgba = r.bytesInto(target) ? target : new Uint8ClampedArray(r.bytes().buffer);
      const width = spec.width || (spec.scene ? 0 : 512);
      const height = rgba.length / 4 / (width || 1);
      this.lastTraceImage = width ? { width, height, rgba } : null;
    }
    return r.text();
  }

  // What a page shows of one step of the trace the last `keep: true` call kept (with `text:
  // false` too, which writes no JSON Lines: a drag's mouse move): {events: the trace's event
  // count, edge_table: face `triangle`'s edge_table event, scanline: its scanline event of row
  // `y`}, each the object its line of the JSON Lines holds, or null.
  keptStep(triangle, y) {
    if (!Number.isInteger(triangle) || triangle < 0 || triangle > 2147483647 || !Number.isInteger(y))
      throw new ScantraceError(`keptStep: a triangle's index and a row, integers (got ${String(triangle)}, ${String(y)})`, 2);
    return JSON.parse(this._call('kept_step', [triangle, y]).text());
  }

  // The same trace as event objects, one per line (header first, footer last).
  trace(input, options = {}) {
    return this.traceText(input, options)
      .split('\n')
      .filter((l) => l.length > 0)
      .map((l) => JSON.parse(l));
  }

  // Display lists of a trace's steps for drawScantraceFrame: {steps, frames}. trace: JSON Lines
  // text or event objects, or null: the trace the last traceText/trace call with `keep: true`
  // recorded in memory (no text parsed again: what the explorer does on every mouse move). options: width, height (1280 × 720), first, count, rows_per_step;
  // blocks: 'rgba' gives the pixel blocks as {width, height, data} (RGBA bytes), drawn at once,
  // instead of PNG data URIs (the default, what `replay`'s pages and the SVG backend write).
  // encoding: 'binary' hands each frame over as numbers instead of JSON text (numbersFrame: the
  // same frame, its lists of numbers as Float64Arrays, its blocks as with blocks: 'rgba'), what
  // the explorer does on every mouse move.
  frames(trace, options = {}) {
    let file = '';
    if (trace !== null) {
      const text = typeof trace === 'string' ? trace : trace.map((e) => JSON.stringify(e)).join('\n') + '\n';
      this.m.FS.writeFile('/in/trace.jsonl', text);
      file = 'trace.jsonl';
    }
    const r = this._call('frames', [file, checkOptions(options)]);
    const out = JSON.parse(r.text());
    if (options.encoding === 'binary') {
      const bytes = new Uint8ClampedArray(r.bytes().buffer);
      out.frames = out.frames.map((head) => numbersFrame(head, bytes));
    } else if (options.blocks === 'rgba') {
      // Each pixel block's op ends with its runs of equal columns and rows and the offset of its
      // texels (one RGBA pixel per run pair) in the result's bytes (web/bindings_trace.cpp's
      // block_runs): some kilobytes instead of the block's 2.3 MB.
      const texels = new Uint8ClampedArray(r.bytes().buffer);
      for (const f of out.frames)
        for (const op of f.ops)
          if (op[0] === 'P') op[7] = runsBlock(op[5], op[6], op[7], texels);
    }
    return out;
  }

  // `scantrace why SCENE X Y --json`'s document; lastWhyText the command's text of it (without
  // --json), made by the module from the same story.
  why(scene, x, y, options = {}) {
    // Doubles to the module (no `| 0`), checked here and there as the command checks them.
    const px = pixelCoordinate(x, 'X'), py = pixelCoordinate(y, 'Y');
    this.lastWhyText = null;
    const r = this._call('why', [this._sceneFile(scene), px, py, checkOptions(options)]);
    this.lastWhyText = decoder.decode(r.bytes());
    return JSON.parse(r.text());
  }

  // Each option's names and default, by the key of its table (src/option_table.hpp: shading,
  // fill_rule, method, winding_rule, cull, visibility, occlusion, level): the names the calls'
  // options take (`winding` takes winding_rule's, `depth` visibility's).
  optionTable() {
    if (!this._options) this._options = JSON.parse(this.m.UTF8ToString(this.m._st_option_table()));
    return structuredClone(this._options);
  }

  // drawScantraceFrame's JavaScript source (viz/frame_json.hpp).
  canvasScript() {
    return this.m.UTF8ToString(this.m._st_canvas_script());
  }

  // The built-in demo scene as scene JSON text.
  demoScene() {
    return this._call('demo_scene', []).text();
  }

  // An image file {name, data} checked as `scantrace diff` checks it before decoding
  // (grade/image_header.hpp): {format, width, height} of a PNG or BMP whose header it accepts
  // (decode it then, e.g. with the browser), or of a .npy, which diff() takes as it is. With the
  // scene it is for (and diff's options), the command's pre-check against the scene's canvas
  // (grade/image_precheck.hpp): a size other than the canvas's adds `report`, diff's report made
  // from the header alone (canvas_size; lastDiffPicture its picture), and there is nothing to
  // decode. Bad input throws ScantraceError with the command's line.
  checkImage(file, scene = null, options = {}) {
    const image = this._imageFile(file);
    const sceneFile = scene === null ? '' : this._sceneFile(scene);
    const r = this._call('image_header', [image, sceneFile, checkOptions(options)]);
    const out = JSON.parse(r.text());
    if (out.report) this._keepPicture(out.report, r);
    return out;
  }

  // The picture of the differences of `report` (the result's bytes), as lastDiffPicture.
  _keepPicture(report, r) {
    const picture = new Uint8ClampedArray(r.bytes().buffer);
    const w = report.canvas ? report.canvas.width : 0;
    this.lastDiffPicture = w ? { width: w, height: picture.length / 4 / w, rgba: picture } : null;
  }

  _imageFile(file) {
    if (!file || typeof file.name !== 'string' || !(file.data instanceof Uint8Array))
      throw new ScantraceError('image file: {name, data} with data a Uint8Array', 2);
    const base = baseName(file.name, 'image', 'image file');
    this.m.FS.writeFile(`/in/${base}`, file.data);
    return base;
  }

  // `scantrace diff SCENE IMAGE --json`'s report. image: {width, height, rgba, name?}, decoded,
  // or a .npy file {name, data}, decoded by the module as the command decodes it.
  // lastDiffPicture: the picture of the last diff's differences, {width, height, rgba}.
  diff(scene, image, options = {}) {
    let r;
    const checked = checkOptions(options);
    if (image && image.data instanceof Uint8Array) {
      r = this._call('diff_npy', [this._sceneFile(scene), this._imageFile(image), checked]);
    } else {
      const { width, height, rgba } = image || {};
      if (!(Number.isInteger(width) && Number.isInteger(height) && width > 0 && height > 0) || !rgba || rgba.length !== width * height * 4)
        throw new ScantraceError('image: {width, height, rgba} with width × height × 4 bytes, or a .npy {name, data}', 2);
      const bytes = rgba instanceof Uint8Array ? rgba : new Uint8Array(rgba.buffer, rgba.byteOffset, rgba.length);
      r = this._call('diff', [this._sceneFile(scene), bytes, width, height, String(image.name || 'image.png'), checked]);
    }
    const report = JSON.parse(r.text());
    this._keepPicture(report, r);
    return report;
  }
}

// Every call of the API throws ScantraceError and nothing else (asScantraceError).
for (const name of ['render', 'traceText', 'trace', 'keptStep', 'frames', 'why', 'optionTable', 'canvasScript', 'demoScene', 'checkImage', 'diff']) {
  const call = Scantrace.prototype[name];
  Scantrace.prototype[name] = function (...args) {
    try {
      return call.apply(this, args);
    } catch (e) {
      throw asScantraceError(e);
    }
  };
}
