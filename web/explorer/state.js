// The explorer's state and its address (#triangle=20,20;250,80;300,400&shading=gouraud&step=12):
// a teacher links a step by copying the address bar. `step` is the index of the step in the
// plan (0 for the first); the address holds the number the page shows, `step 12` for step=12,
// as the trace page's #step=12 does.
export const defaults = {
  mode: 'triangle',
  triangle: [[20, 20], [250, 80], [300, 400]],
  // Polygon mode: one closed contour (a star: it crosses itself, so the winding rule shows).
  polygon: [[256, 40], [380, 440], [60, 190], [450, 190], [130, 440]],
  winding: 'even-odd',
  colors: [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
  size: [512, 512],
  shading: 'gouraud',
  fill_rule: 'top-left',
  subpixel_bits: 8,
  method: 'exact',
  // Scanlines a step: 0 lets the composer choose (at most 40 scanline steps a triangle).
  rows_per_step: 0,
  step: 0,
};

const hex = (c) => '#' + c.map((v) => Math.round(v * 255).toString(16).padStart(2, '0')).join('');
export const toHex = hex;
export const fromHex = (h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16) / 255);

export function toHash(s) {
  const p = new URLSearchParams();
  if (s.mode === 'triangle') p.set('triangle', s.triangle.map((v) => v.join(',')).join(';'));
  else if (s.mode === 'polygon') {
    p.set('polygon', s.polygon.map((v) => v.join(',')).join(';'));
    p.set('winding', s.winding);
  } else p.set('scene', s.sceneName || 'demo');
  p.set('colors', s.colors.map((c) => hex(c).slice(1)).join(';'));
  p.set('size', s.size.join('x'));
  for (const k of ['shading', 'fill_rule', 'subpixel_bits', 'method']) p.set(k, String(s[k]));
  if (s.rows_per_step) p.set('rows', String(s.rows_per_step));
  p.set('step', String(s.step + 1));
  return '#' + p.toString().replace(/%2C/g, ',').replace(/%3B/g, ';');
}

// The state in `hash`, each value checked; what is missing or malformed keeps its default.
export function fromHash(hash) {
  const s = structuredClone(defaults);
  const p = new URLSearchParams(hash.replace(/^#/, ''));
  const num = (t) => (/^-?\d+(\.\d+)?(e-?\d+)?$/i.test(t) ? Number(t) : NaN);
  if (p.has('triangle')) {
    const v = p.get('triangle').split(';').map((xy) => xy.split(',').map(num));
    if (v.length === 3 && v.every((xy) => xy.length === 2 && xy.every(Number.isFinite))) s.triangle = v;
  }
  if (p.has('polygon')) {
    const v = p.get('polygon').split(';').map((xy) => xy.split(',').map(num));
    if (v.length >= 3 && v.length <= 64 && v.every((xy) => xy.length === 2 && xy.every(Number.isFinite))) {
      s.polygon = v;
      s.mode = 'polygon';
    }
  }
  if (['even-odd', 'non-zero'].includes(p.get('winding'))) s.winding = p.get('winding');
  if (p.has('scene')) {
    s.mode = 'scene';
    s.sceneName = p.get('scene');
  }
  if (p.has('colors')) {
    const c = p.get('colors').split(';');
    if (c.length === 3 && c.every((h) => /^[0-9a-f]{6}$/i.test(h))) s.colors = c.map((h) => fromHex('#' + h));
  }
  if (p.has('size')) {
    const m = /^(\d+)x(\d+)$/.exec(p.get('size'));
    if (m && +m[1] > 0 && +m[2] > 0 && +m[1] <= 4096 && +m[2] <= 4096) s.size = [+m[1], +m[2]];
  }
  if (['flat', 'gouraud'].includes(p.get('shading'))) s.shading = p.get('shading');
  if (['top-left', 'closed'].includes(p.get('fill_rule'))) s.fill_rule = p.get('fill_rule');
  if (['exact', 'float', 'double', 'halfspace'].includes(p.get('method'))) s.method = p.get('method');
  const bits = num(p.get('subpixel_bits') || '');
  if (Number.isInteger(bits) && bits >= 0 && bits <= 12) s.subpixel_bits = bits;
  const rows = num(p.get('rows') || '');
  if ([1, 10].includes(rows)) s.rows_per_step = rows;
  const step = num(p.get('step') || '');
  if (Number.isInteger(step) && step >= 1) s.step = step - 1;
  return s;
}
