// The explorer's answers (web/explorer/answers.js): a why story's answer sentence, made from the
// last line of `scantrace why`'s text (the module's lastWhyText), and a diff's verdict as
// `scantrace diff`'s Markdown says it.
//
//   node web/tests/node_answers.mjs
import assert from 'node:assert/strict';

import { diffSummary, whyProse } from '../explorer/answers.js';

// The text is shown as the module gave it; the answer is its last line, pixel named first. A face
// that wrote the pixel is said in the middle of the text, so an answer read from any other line
// than the last names the wrong thing.
const text = 'pixel (3, 4) of the 8x8 canvas (flat, top-left rule, painter):\n' +
  '  1. face 2 (depth 0.5): covers it: row 4 has active points x_L = 1.5 (edge 0) and x_R = 6.25 (edge 2), span 2..6; ' +
  'flat colour (the mean of the vertex colours) (0.0312, 0.0001, 0.6667); written\n' +
  '  final colour (0.0312, 0.0001, 0.6667), written by face 2\n';
const prose = whyProse({ pixel: [3, 4] }, text);
assert.equal(prose.answer, 'Pixel (3, 4): final colour (0.0312, 0.0001, 0.6667), written by face 2.');
assert.equal(prose.text, text);
const background = whyProse({ pixel: [0, 7] }, 'pixel (0, 7) of the 8x8 canvas (flat, top-left rule, painter):\n' +
  "  no face's bounding box holds its centre\n  final colour (0.0000, 0.0000, 0.0000), the background (no face wrote it)\n");
assert.equal(background.answer, 'Pixel (0, 7): final colour (0.0000, 0.0000, 0.0000), the background (no face wrote it).');

// A diff's verdict: to_markdown's sentence, two decimals of the percentage.
const summary = diffSummary({ agrees: false, compared_pixels: 262144, differing_pixels: 35315, global: [], patterns: [], notes: [],
  categories: { colour: 35293, background: 22, boundary: 0 }, near_boundary: { extra: 0, missing: 0 }, colour: { max_error: 0.6627, diagnosis: [] }, faces: [] });
assert.equal(summary.verdict, '35315 of 262144 pixels differ (13.47 %).');
assert.deepStrictEqual(summary.legend.map((l) => l[0]), ['colour', 'background']);
// With the mistakes the command names first (report.verdict), they are the verdict, in their
// order, and the counts come next.
const named = diffSummary({ agrees: false, compared_pixels: 100, differing_pixels: 7, global: [], patterns: [], notes: [],
  categories: { order: 7 }, near_boundary: { extra: 0, missing: 0 }, colour: { max_error: 0, diagnosis: [] }, faces: [],
  verdict: [{ id: 'order_reversed', text: 'faces are painted nearest first', evidence: '7 pixels' },
            { id: 'bottom_row_dropped', text: 'the last row of each triangle is missing', evidence: '' }] });
assert.equal(named.verdict, 'faces are painted nearest first; the last row of each triangle is missing');
assert.equal(named.lines[0], '7 of 100 pixels differ (7.00 %).');
console.log('explorer answers: the why answer from the command\'s text, the diff verdict in its words');
