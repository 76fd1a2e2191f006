// The trace page's module (web/player/player_module.cpp, scantrace_player.mjs + .wasm) as the
// player calls it: a trace opened once, then one step's frame at a time. In a page (make_page.mjs
// inlines it) and in Node (web/tests/node_player.mjs) alike: the caller hands over the .wasm bytes.
//
//   const pm = await loadPlayer(wasmBytes);
//   const { steps } = pm.open(traceText, { width: 1280, height: 720 });
//   drawScantraceFrame(ctx, pm.frame(0));   // web/player/frame_draw.js, inlined by the page
import createScantracePlayer from './scantrace_player.mjs';

export async function loadPlayer(wasmBinary) {
  const m = await createScantracePlayer({ wasmBinary, print: () => {}, printErr: () => {} });
  const decoder = new TextDecoder();
  // A C string in the module's memory for the call, freed after it.
  const withString = (text, use) => {
    const n = m.lengthBytesUTF8(text) + 1;
    const p = m._malloc(n);
    m.stringToUTF8(text, p, n);
    try {
      return use(p);
    } finally {
      m._free(p);
    }
  };
  // The call's result text parsed, or its message thrown (status 1: bad input, 2: bad argument).
  const result = (status) => {
    if (status !== 0) {
      const e = new Error(m.UTF8ToString(m._st_page_error()));
      e.status = status;
      throw e;
    }
    const at = m._st_page_text();
    return JSON.parse(decoder.decode(m.HEAPU8.subarray(at, at + m._st_page_text_size())));
  };
  return {
    // {steps: [{kind, triangle, first_row, last_row, view?, origin?, cell?}, …]}; options as the
    // full module's frames() takes them (width, height, rows_per_step, mode, source, marked_pixel).
    open: (traceText, options = {}) =>
      result(withString(traceText, (t) => withString(JSON.stringify(options), (o) => m._st_page_open(t, o)))),
    // Step `index`'s frame (0-based, of all the steps open() listed), for drawScantraceFrame.
    frame: (index) => result(m._st_page_frame(index)),
  };
}
