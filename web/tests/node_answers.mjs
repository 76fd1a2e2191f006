// The explorer's numbers as `scantrace why` writes them (web/explorer/answers.js): fmt's {:.6g}
// and {:.4f}, a tie rounded to even, against printf's %.6g and %.4f of the same doubles (the
// values written here as C's printf prints them; Python's '%.6g' % v gives the same).
//
//   node web/tests/node_answers.mjs
import assert from 'node:assert/strict';

import { diffSummary, general6, whyProse } from '../explorer/answers.js';

const g6 = [
  [254.0625, '254.062'], // a tie: to even (toPrecision gives 254.063)
  [254.0635, '254.064'], // not a tie in binary (254.06349999…?): printf's digits
  [83.36842105263158, '83.3684'], [0, '0'], [-0, '-0'], [1, '1'], [0.03125, '0.03125'],
  [1 / 3, '0.333333'], [250, '250'], [123456.5, '123456'], [123457.5, '123458'], [1234567, '1.23457e+06'],
  [0.0001234, '0.0001234'], [0.00001234, '1.234e-05'], [999999.5, '1e+06'], [9.999995, '10'],
  [-2.5, '-2.5'], [1e-7, '1e-07'], [64.2105263, '64.2105'], [0.999634, '0.999634'],
];
for (const [v, want] of g6) assert.equal(general6(v), want, `%.6g of ${v}`);

// {:.4f} through a why story's colours: 0.03125 is a tie (0.0312), 0.00005 rounds up (its double
// is above 5e-5), 2/3 0.6667.
const story = {
  pixel: [3, 4], canvas: { width: 8, height: 8 }, shading: 'flat', fill_rule: 'top-left', visibility: 'painter',
  faces: [{ face: 2, depth: 0.5, outcome: 'written', rows: [1, 6], active_points: [{ x: 1.5, edge: 0, color: [1, 0, 0] }, { x: 6.25, edge: 2, color: [0, 0, 1] }],
    span: { x_begin: 2, x_end: 7 }, color: [0.03125, 0.00005, 2 / 3], t: 0.25 }],
  notes: [], final: { color: [0.03125, 0.00005, 2 / 3], face: 2 },
};
const prose = whyProse(story);
assert.equal(prose.answer, 'Pixel (3, 4): final colour (0.0312, 0.0001, 0.6667), written by face 2.');
assert.equal(prose.text, 'pixel (3, 4) of the 8x8 canvas (flat, top-left rule, painter):\n' +
  '  1. face 2 (depth 0.5): covers it: row 4 has active points x_L = 1.5 (edge 0) and x_R = 6.25 (edge 2), span 2..6; ' +
  'flat colour (the mean of the vertex colours) (0.0312, 0.0001, 0.6667); written\n' +
  '  final colour (0.0312, 0.0001, 0.6667), written by face 2\n');

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
console.log('explorer answers: the command\'s number formats and sentences');
