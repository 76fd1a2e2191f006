// Checks of a page's layout at a screen size, in headless Chromium over the DevTools protocol
// (cdp.mjs's browser `b`), shared by the tests of the pages at lecture and phone sizes.
import fs from 'node:fs';
import path from 'node:path';

// A text's size as a CSS font size: the height of its capitals and digits over 0.7, the share of
// the font size a sans-serif's capitals take (system-ui's, the pages' font: about 0.7).
export const kCapitals = 0.7;
export const kReadable = 10;

// A laptop on a projector, a desktop, a phone held upright (touch, mobile).
export const sizes = [
  { name: '1366x768', width: 1366, height: 768, mobile: false },
  { name: '1920x1080', width: 1920, height: 1080, mobile: false },
  { name: '390x844', width: 390, height: 844, mobile: true },
];

// A screenshot as DIR/NAME.png: the window, or (`whole`) the whole page.
export async function screenshot(b, dir, name, whole = false) {
  const params = { format: 'png' };
  if (whole) {
    const [w, h] = await b.evaluate('[document.documentElement.scrollWidth, document.documentElement.scrollHeight]');
    Object.assign(params, { captureBeyondViewport: true, clip: { x: 0, y: 0, width: w, height: h, scale: 1 } });
  }
  const { data } = await b.page('Page.captureScreenshot', params);
  fs.writeFileSync(path.join(dir, `${name}.png`), Buffer.from(data, 'base64'));
}

// The controls (and labels) seen, any part of them outside the screen's width; and how wide the
// page is. One inside a box that scrolls sideways (a phone's frame) is reached by scrolling it:
// the box is checked instead. (A phone's window grows to a page wider than the screen, so the
// screen's width is the emulated one, not innerWidth.)
export const cutOff = (b, width) => b.evaluate(`((innerWidth) => {
  const seen = (el) => { const r = el.getBoundingClientRect(); return r.width > 1 && r.height > 1 && getComputedStyle(el).visibility !== 'hidden'; };
  const scrolls = (el) => ['auto', 'scroll'].includes(getComputedStyle(el).overflowX);
  const shown = (el) => { for (let a = el.parentElement; a && a !== document.body; a = a.parentElement) if (scrolls(a)) return a; return el; };
  const out = [...document.querySelectorAll('button, select, input, label, summary, a, [tabindex]')]
    .filter(seen).map(shown).filter((el) => { const r = el.getBoundingClientRect(); return r.left < -0.5 || r.right > innerWidth + 0.5; })
    .map((el) => el.id || el.textContent.trim().slice(0, 30) || el.tagName);
  return { out, scroll: document.documentElement.scrollWidth, width: innerWidth };
})(${width})`);

// Each element holding text: the lines of its own text outside its box (more than half a pixel),
// or, for a box that clips without scrolling, its content wider or taller than the box. A select
// draws its option itself; a box of 1 px is a live region, said and never seen.
export const overflowing = (b) => b.evaluate(`(() => {
  const bad = [];
  for (const el of document.querySelectorAll('body *')) {
    const r = el.getBoundingClientRect(), style = getComputedStyle(el);
    if (r.width <= 1 || r.height <= 1 || style.visibility === 'hidden' || el.closest('select')) continue;
    for (const node of el.childNodes) {
      if (node.nodeType !== Node.TEXT_NODE || !node.textContent.trim()) continue;
      const range = document.createRange();
      range.selectNodeContents(node);
      for (const line of range.getClientRects())
        if (line.left < r.left - 0.5 || line.right > r.right + 0.5 || line.top < r.top - 0.5 || line.bottom > r.bottom + 0.5)
          bad.push(\`"\${node.textContent.trim().slice(0, 40)}" in \${el.id || el.tagName} (\${Math.round(line.left)}..\${Math.round(line.right)} of \${Math.round(r.left)}..\${Math.round(r.right)})\`);
    }
    const clips = (v) => v === 'hidden' || v === 'clip';
    if ((clips(style.overflowX) && el.scrollWidth > el.clientWidth + 1) || (clips(style.overflowY) && el.scrollHeight > el.clientHeight + 1))
      bad.push(\`\${el.id || el.tagName} clips its content (\${el.scrollWidth}x\${el.scrollHeight} in \${el.clientWidth}x\${el.clientHeight})\`);
  }
  return bad;
})()`);

// The page's smallest font size among the texts seen, and where.
export const smallestPageFont = (b) => b.evaluate(`(() => {
  let page = Infinity, where = '';
  for (const el of document.querySelectorAll('body *')) {
    const r = el.getBoundingClientRect();
    if (r.width <= 1 || r.height <= 1 || el.closest('select')) continue;
    if (![...el.childNodes].some((n) => n.nodeType === Node.TEXT_NODE && n.textContent.trim())) continue;
    const size = parseFloat(getComputedStyle(el).fontSize);
    if (size < page) [page, where] = [size, el.id || el.tagName];
  }
  return { page, where };
})()`);

// Frame f's smallest text as a font size in CSS pixels, shown `css` CSS pixels a frame pixel:
// of each text op holding a capital or a digit, the tallest glyph (its strokes' extent), over
// kCapitals. {size, which: the text}.
export function frameTextSize(f, css) {
  let size = Infinity, which = '';
  for (const op of f.ops) {
    if (op[0] !== 'G' || !/[A-Z0-9]/.test(op[3])) continue;
    let most = 0;
    for (let k = 0; k < op[6].length; k += 3) {
      const ys = f.glyphs[op[6][k]].flatMap((s) => s.filter((v, i) => i % 2 === 1));
      if (ys.length) most = Math.max(most, Math.max(...ys) - Math.min(...ys));
    }
    if (most * css / kCapitals < size) [size, which] = [most * css / kCapitals, op[3]];
  }
  return { size, which };
}

// Names of what a person operates or sees as a picture, missing in the browser's accessibility
// tree: [role, DOM node id] of each unnamed one.
export async function unnamedControls(b) {
  await b.page('Accessibility.enable');
  const { nodes } = await b.page('Accessibility.getFullAXTree', {});
  const roles = ['button', 'combobox', 'slider', 'textbox', 'spinbutton', 'image', 'img', 'ColorWell', 'checkbox', 'link'];
  return nodes.filter((n) => !n.ignored && roles.includes(n.role?.value) && !(n.name?.value || '').trim()).map((n) => `${n.role.value} ${n.backendDOMNodeId}`);
}
