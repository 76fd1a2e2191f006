// The step page's player (viz/step_page.hpp): steps of pre-drawn frames (WebP or gzipped SVG)
// shown in an <img>, on the player core every page shares (controller.mjs, bind.mjs, keys.json).
// The page's template (step_page.html) defines DATA before this script and SCANTRACE_KEYS (the
// key table) with it (cmake/web_player.cmake). Why plain script and no framework: the page must
// work offline from a single file, in any browser of the last years, and stay small next to the
// frames it carries.
/* global DATA, SCANTRACE_KEYS */
import { bindPlayer } from './bind.mjs';
import { createStepper } from './controller.mjs';
import { playerKeys } from './keys.mjs';

export function startStepPage() {
  const $ = (id) => document.getElementById(id);
  const n = DATA.frames.length, base = DATA.first; // steps base .. base + n - 1
  const img = $('frame'), status = $('status'), list = $('list');
  img.width = DATA.width;
  img.height = DATA.height;
  list.start = base;
  const say = (text) => { status.textContent = text; };
  const frameUrl = frameUrls(DATA);
  const s = createStepper({
    count: n, rows: DATA.rows, say, speed: DATA.fps,
    show(i) {
      frameUrl(i).then((url) => { if (s.index === i) img.src = url; },
        (e) => say(`cannot show step ${base + i}: ${e}`));
      document.title = `${DATA.title} - step ${base + i}`;
      img.alt = `the frame of step ${base + i}: ${DATA.labels[i]}`;
    },
  });
  DATA.labels.forEach((label, i) => {
    const li = document.createElement('li');
    li.textContent = label;
    li.addEventListener('click', () => s.go(i));
    list.appendChild(li);
  });
  const keys = playerKeys(SCANTRACE_KEYS, 'step');
  // The hint under the frame: a few of the key table's rows (? shows them all).
  $('hint').textContent = keys.hint(['next', 'previous', 'go_to_row', 'play', 'save', 'help']);
  bindPlayer(s, {
    scope: document, keys, first: base, slider: $('slider'),
    counter: $('counter'), counterText: () => `step ${base + s.index} / ${DATA.total}`, list,
    playButton: $('play'), speed: $('speed'), help: $('help'), hash: true, say,
    announce: $('announce'), sentence: () => `step ${base + s.index} / ${DATA.total}: ${DATA.labels[s.index]}`,
    actions: { save: () => save(frameUrl, base + s.index, s.index, say) },
  });
  s.go(s.initialIndex);
}

// A frame as an address the <img> can show. Gzipped frames (the SVG page) are inflated when
// first shown, not all at load: the page opens at once whatever its length.
function frameUrls(data) {
  const urls = data.gzip ? [] : data.frames;
  const url = (i) => {
    if (urls[i]) return Promise.resolve(urls[i]);
    const bytes = Uint8Array.from(atob(data.frames[i]), (c) => c.charCodeAt(0));
    const inflated = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
    return new Response(inflated).arrayBuffer().then((b) => {
      urls[i] = URL.createObjectURL(new Blob([b], { type: data.mime }));
      return urls[i];
    });
  };
  url.ready = (i) => urls[i];
  return url;
}

// The shown frame as a file download: step_00012.webp.
function save(frameUrl, step, i, say) {
  if (!frameUrl.ready(i)) return say(`step ${step} is still being drawn`);
  const a = document.createElement('a');
  a.href = frameUrl.ready(i);
  a.download = `step_${String(step).padStart(5, '0')}.${DATA.extension}`;
  document.body.appendChild(a);
  a.click();
  a.remove();
  say(`saved ${a.download}`);
}
