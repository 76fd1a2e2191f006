// The explorer page (docs/web.md): drag a triangle's vertices on the pixel grid and watch the
// real fill (the WebAssembly module) redo its edge table, active edge list and spans; step
// through the composer's frames with `scantrace step`'s keys; click a pixel for its `why`; open a
// scene; drop an image rendered for it for a `diff`. The state is kept in the address.
// The modules: state.js (the address, the state `ex` and the model), view.js (drawing),
// controller.js (input), controls.js (the player), answers.js (why and diff in words).
import { ex, fromHash } from './state.js';
import { $, bindDiffToggle } from './view.js';
import { bindModes, bindOptions, bindPointer, bindPresent, bindWindow, exposeForTests, openAddress } from './controller.js';

export async function start(st) {
  ex.st = st;
  ex.drawFrame = new Function(`${st.canvasScript()}; return drawScantraceFrame;`)();
  ex.s = fromHash(location.hash);
  ex.grid = $('grid');
  ex.gctx = ex.grid.getContext('2d');
  ex.frame = $('frame');
  ex.fctx = ex.frame.getContext('2d');
  ex.fillCanvas = $('fill');
  ex.frameBoxWidth = ex.frame.clientWidth;
  ex.gridBoxWidth = ex.grid.clientWidth;
  bindDiffToggle();
  bindPointer();
  bindOptions();
  bindPresent();
  bindModes();
  bindWindow();
  openAddress();
  exposeForTests();
  // Milliseconds from navigation to a working page (the test prints it; docs/performance.md).
  document.body.dataset.readyMs = performance.now().toFixed(0);
  document.body.dataset.ready = '1';
}
