// The explorer's answers in prose (docs/web.md): a pixel's `why` as `scantrace why`'s own text
// (grade/pixel_story.cpp's PixelStory::to_text, which the module hands over with the story's JSON),
// with its answer in front, and a diff as its summary (grade/diff_report.cpp's to_markdown: the
// verdict, the counts, the patterns) with the legend of the diff picture's colours
// (grade/diff_picture.cpp's kCategoryColours). Names here are unique across the explorer's
// modules: make_page.mjs puts them all in one scope.

// The answer first (the final colour and who wrote it, the text's last line), then the text:
// `scantrace why`'s own words, which the module made of the same story (lastWhyText).
export function whyProse(story, text) {
  const [x, y] = story.pixel;
  const final = text.trimEnd().split('\n').pop().trim();
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
