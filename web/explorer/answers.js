// The explorer's answers in prose (docs/web.md): a pixel's `why` as `scantrace why`'s own text
// (grade/pixel_story.cpp's PixelStory::to_text, rebuilt here from the module's JSON, which is all
// the module hands over), and a diff as its summary (grade/diff_report.cpp's to_markdown: the
// verdict, the counts, the patterns) with the legend of the diff picture's colours
// (grade/diff_picture.cpp's kCategoryColours). Names here are unique across the explorer's
// modules: make_page.mjs puts them all in one scope.

// fmt's {:.4f} and {:.6g} (printf's %.4f and %.6g), as the command writes its numbers: rounded
// from the double's exact decimal digits, a tie to even (254.0625 is 254.062; JavaScript's
// toFixed and toPrecision round a tie up).
function roundedDigits(a, p) {
  // a > 0: its first p significant digits, rounded, and the exponent of the first.
  const [m, power] = a.toExponential(Math.min(100, p + 25)).split('e');
  const all = m.replace('.', '');
  const d = all.slice(0, p).split('').map(Number);
  const rest = all.slice(p);
  let e = Number(power);
  if (rest[0] > '5' || (rest[0] === '5' && (/[1-9]/.test(rest.slice(1)) || d[p - 1] % 2 === 1))) {
    let i = p - 1;
    while (i >= 0 && d[i] === 9) d[i--] = 0;
    if (i < 0) {
      d.unshift(1);
      d.pop();
      ++e;
    } else ++d[i];
  }
  return [d.join(''), e];
}
const signOf = (v) => (v < 0 || Object.is(v, -0) ? '-' : '');
function fixed4(v) {
  const a = Math.abs(v);
  const e0 = a === 0 ? -99 : Number(a.toExponential(25).split('e')[1]);
  // The digits of a x 10^4 rounded to an integer (below 10^-5 it has none: 0, or 1 from 5e-5).
  let n = a >= 5e-5 ? '1' : '0';
  if (e0 >= -4) {
    const [ds, e] = roundedDigits(a, e0 + 5);
    n = ds + '0'.repeat(e - e0);
  }
  n = n.padStart(5, '0');
  return `${signOf(v)}${n.slice(0, -4)}.${n.slice(-4)}`;
}
export function general6(v) {
  const a = Math.abs(v);
  if (a === 0) return `${signOf(v)}0`;
  const [ds, e] = roundedDigits(a, 6);
  const trim = (f) => f.replace(/0+$/, '');
  let body;
  if (e < -4 || e >= 6) {
    const frac = trim(ds.slice(1));
    body = `${ds[0]}${frac ? '.' + frac : ''}e${e < 0 ? '-' : '+'}${String(Math.abs(e)).padStart(2, '0')}`;
  } else {
    const whole = e >= 0 ? ds.slice(0, e + 1) : '0';
    const frac = trim(e >= 0 ? ds.slice(e + 1) : '0'.repeat(-e - 1) + ds);
    body = frac ? `${whole}.${frac}` : whole;
  }
  return signOf(v) + body;
}
const rgbText = (c) => `(${c.map(fixed4).join(', ')})`;

// The sentence of one face: what the fill did about pixel (x, y) (face_sentence).
function whyFaceSentence(f, x, y, gouraud) {
  const out = `face ${f.face} (depth ${general6(f.depth)}): `;
  if (f.outcome === 'skipped') return `${out}skipped by the fill (${f.reason})`;
  const [first, last] = f.rows || [0, -1];
  if (f.outcome === 'row_outside')
    return `${out}does not cover it: row ${y} is not among its scanlines ${first}..${last} (ceil(y_min) .. ceil(y_max) - 1)`;
  const pts = f.active_points || [];
  const l = pts[0], r = pts[pts.length - 1];
  const row = pts.length >= 2 ? `row ${y} has active points x_L = ${general6(l.x)} (edge ${l.edge}) and x_R = ${general6(r.x)} (edge ${r.edge})` : '';
  const span = f.span ? `span ${f.span.x_begin}..${f.span.x_end - 1}` : 'an empty span';
  if (f.outcome === 'left_of_span' || f.outcome === 'right_of_span')
    return `${out}does not cover it: ${row}, ${span} (ceil(x_L) .. ceil(x_R) - 1); x = ${x} is ${f.outcome === 'left_of_span' ? 'left' : 'right'} of it`;
  if (f.outcome !== 'written' && f.outcome !== 'depth_rejected') return out;
  let text = `${out}covers it: ${row}, ${span}; `;
  text += gouraud && pts.length >= 2
    ? `Gouraud: edge colours ${rgbText(l.color)} and ${rgbText(r.color)}, t = ${general6(f.t)} along the span gives ${rgbText(f.color)}`
    : `flat colour (the mean of the vertex colours) ${rgbText(f.color)}`;
  const d = f.depth_test;
  if (!d) return `${text}; written`;
  const stored = d.stored === undefined ? 'empty' : general6(d.stored);
  return `${text}; depth test: depth ${general6(d.depth)} vs stored ${stored}: ${d.passed ? 'passes, written' : 'fails, not written'}`;
}

// The answer first (the final colour and who wrote it), then `scantrace why`'s text.
export function whyProse(story) {
  const [x, y] = story.pixel;
  const fin = story.final;
  const final = `final colour ${rgbText(fin.color)}${fin.face === null ? ', the background (no face wrote it)' : `, written by face ${fin.face}`}`;
  let text = `pixel (${x}, ${y}) of the ${story.canvas.width}x${story.canvas.height} canvas (${story.shading}, ${story.fill_rule} rule, ${story.visibility}):\n`;
  if (!story.faces.length) text += "  no face's bounding box holds its centre\n";
  story.faces.forEach((f, i) => {
    text += `  ${i + 1}. ${whyFaceSentence(f, x, y, story.shading === 'gouraud')}\n`;
  });
  for (const n of story.notes) text += `  note: ${n}\n`;
  text += `  ${final}\n`;
  return { answer: `Pixel (${x}, ${y}): ${final}.`, text };
}

// The diff picture's colours, category by category (grade/diff_picture.cpp), and its grey: the
// reference where the image agrees.
export const diffCategoryColours = {
  boundary: [230, 0, 0], near_boundary: [255, 140, 0], widened: [120, 200, 40], shifted: [200, 200, 0],
  order: [200, 0, 200], order_tie: [230, 160, 230], missing_face: [0, 90, 230], degenerate_drawn: [40, 40, 40],
  colour: [0, 170, 0], background: [0, 200, 200], other: [120, 60, 120],
};

const percentOf = (n, of) => (of > 0 ? (100 * n) / of : 0);

// The report's summary, in to_markdown's words: {verdict, lines, legend: [[category, count, rgb]]}.
export function diffSummary(r) {
  if (r.agrees) return { verdict: `The image agrees with the reference (${r.compared_pixels} pixels compared).`, lines: r.notes.map((n) => `Note: ${n}`), legend: [] };
  const lines = [];
  for (const g of r.global) lines.push(`Global mistake: ${g.text}${g.undone ? ' (undone before classifying the pixels)' : ''}`);
  const legend = Object.entries(r.categories).filter(([, n]) => n > 0).sort((a, b) => b[1] - a[1])
    .map(([c, n]) => [c, n, diffCategoryColours[c]]);
  for (const p of r.patterns) lines.push(`Pattern: ${p}`);
  if (r.near_boundary.extra + r.near_boundary.missing > 0)
    lines.push(`Near the boundary: ${r.near_boundary.extra} extra pixels (outside their face), ${r.near_boundary.missing} missing (inside their face).`);
  if (r.categories.colour > 0) {
    lines.push(`Colour: max error ${r.colour.max_error.toFixed(4)} per channel.`);
    for (const d of r.colour.diagnosis) lines.push(`Colour: ${d}`);
  }
  for (const f of r.faces) lines.push(`Face ${f.face}: ${f.pixels} pixels, mostly ${f.category}.`);
  for (const n of r.notes) lines.push(`Note: ${n}`);
  const counts = `${r.differing_pixels} of ${r.compared_pixels} pixels differ (${percentOf(r.differing_pixels, r.compared_pixels).toFixed(2)} %).`;
  // The mistakes named in the catalogue's words come first, as `scantrace diff` prints them
  // (report.verdict: [{id, text, evidence}]); the counts follow. Without a verdict, the counts.
  const said = (r.verdict || []).map((v) => v.text);
  const verdict = said.length ? said.join('; ') : counts;
  if (said.length) lines.unshift(counts);
  return { verdict, lines, legend: legend.map(([c, n, rgb]) => [c, n, rgb, percentOf(n, r.differing_pixels)]) };
}
