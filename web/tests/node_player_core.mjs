// The player core every page shares (web/player/: keys.json, keys.mjs, controller.mjs), in Node
// without a browser or a module:
// - the key table: the keys a player has, as `scantrace step`'s keys are (written out here by
//   hand), none with Ctrl, Alt or Meta; every action a page's table lists is one the core or the
//   page does;
// - stepping: clamped to the steps, ten at a time, first and last;
// - g, a row, Enter: the step whose scanlines hold that row (rows written here), Backspace and
//   Esc, a row no step shows;
// - play: one step per 1/speed seconds on a fake clock, faster and slower changing the interval
//   while playing, stopping at the last step.
// node_player.mjs imports it (the checks run with the module's); alone: node node_player_core.mjs
import assert from 'node:assert/strict';
import fs from 'node:fs';

import { createStepper, PLAY_SPEEDS } from '../player/controller.mjs';
import { controlsKey, playerKeys } from '../player/keys.mjs';
import { check, summary } from './check.mjs';

const table = JSON.parse(fs.readFileSync(new URL('../player/keys.json', import.meta.url), 'utf8'));
const key = (k, mods = {}) => ({ key: k, ctrlKey: false, altKey: false, metaKey: false, ...mods });

check('the key table: the trace page has the keys of scantrace step, and its own', () => {
  const keys = playerKeys(table, 'trace');
  const expected = {
    ArrowRight: 'next', ' ': 'next', n: 'next', ArrowLeft: 'previous', p: 'previous',
    PageDown: 'forward10', PageUp: 'back10', Home: 'first', End: 'last', g: 'go_to_row',
    a: 'play', '+': 'faster', '-': 'slower', r: 'toggle_rows', c: 'copy_link', '?': 'help',
    Escape: 'close', s: null, q: null, x: null,
  };
  for (const [k, action] of Object.entries(expected)) assert.strictEqual(keys.action(key(k)), action, k);
  assert.strictEqual(keys.action(key('n', { ctrlKey: true })), null);
  assert.strictEqual(playerKeys(table, 'step').action(key('s')), 'save');
  assert.strictEqual(playerKeys(table, 'python').action(key('c')), null);
  // The help lists each action once, with its label, and not the closing Esc.
  const help = keys.help();
  assert.ok(help.some(([label, text]) => label === '?' && /keys/.test(text)), JSON.stringify(help));
  assert.ok(help.some(([label]) => label.startsWith('g')));
  assert.ok(!help.some(([label]) => label === 'Esc'));
  // The pages' one-line hint: the named actions the player has, in the table's order, as written
  // here from the trace page's keys (s is the step page's, not the trace page's).
  assert.strictEqual(keys.hint(['help', 'save', 'next']), '\u2192 / space / n next step \u00b7 ? these keys (Esc closes)');
});

check("every action of a page's keys is done by the core or by the page", () => {
  const stepper = createStepper({ count: 3, show: () => {} });
  const pages = { trace: ['help', 'close', 'copy_link', 'toggle_rows'], step: ['help', 'close', 'copy_link', 'save'],
    python: ['help', 'close'] };
  for (const [player, own] of Object.entries(pages))
    for (const a of table.actions.filter((x) => x.in.includes(player)))
      assert.ok(own.includes(a.action) || stepper.act(a.action), `${player}: ${a.action}`);
});

check("the focus rules: a text field's keys and a button's Space and Enter are the control's; a list's arrows are not", () => {
  const event = (tagName, k, type) => {
    const e = { key: k, target: { tagName, type, blurred: false, blur() { this.blurred = true; } }, prevented: false };
    e.preventDefault = () => { e.prevented = true; };
    return e;
  };
  for (const type of ['text', 'number', 'search']) assert.strictEqual(controlsKey(event('INPUT', 'n', type)), true, type);
  assert.strictEqual(controlsKey(event('INPUT', 'ArrowRight', 'range')), false);
  for (const tag of ['BUTTON', 'SUMMARY']) {
    assert.strictEqual(controlsKey(event(tag, ' ')), true, tag);
    assert.strictEqual(controlsKey(event(tag, 'Enter')), true, tag);
    assert.strictEqual(controlsKey(event(tag, 'n')), false, tag);
  }
  // A list: left, its ↑ ↓ kept from changing its value, its ← → the player's.
  const down = event('SELECT', 'ArrowDown'), right = event('SELECT', 'ArrowRight');
  assert.deepStrictEqual([controlsKey(down), down.target.blurred, down.prevented], [false, true, true]);
  assert.deepStrictEqual([controlsKey(right), right.target.blurred, right.prevented], [false, true, false]);
});

// 12 steps: a title, set-up, then rows 5..9, 10..14, ... two rows a step up to 24, then the end.
const rows = [null, null, [5, 9], [10, 14], [15, 19], [20, 24], null];
function stepper(extra = {}) {
  const shown = [], said = [];
  const s = createStepper({ count: rows.length, rows, show: (i) => shown.push(i), say: (t) => said.push(t), ...extra });
  return { s, shown, said };
}

check('steps are clamped; ten at a time; first and last', () => {
  const { s, shown } = stepper();
  s.act('previous');
  s.act('forward10');
  s.act('next');
  s.act('back10');
  s.go(3);
  s.act('last');
  s.act('first');
  assert.deepStrictEqual(shown, [0, 6, 6, 0, 3, 6, 0]);
});

check('g, a row, Enter: the step of that scanline; Backspace, Esc; a row no step shows', () => {
  const { s, said } = stepper();
  // A key as the page's keydown hands it over: with its part in the row from the key table.
  const keys = playerKeys(table, 'trace');
  const type = (k) => s.typeRow(keys.rowKey(k), k);
  // The row's keys, as `scantrace step`'s are (written out here by hand).
  for (const k of '0123456789-') assert.strictEqual(keys.rowKey(k), 'characters', k);
  const parts = { Enter: 'go', Backspace: 'erase', Escape: 'cancel', x: null, q: null, '+': null, g: null };
  for (const [k, part] of Object.entries(parts)) assert.strictEqual(keys.rowKey(k), part, k);
  s.act('go_to_row');
  assert.ok(s.typingRow);
  for (const k of ['1', '9', 'Backspace', '7', 'Enter']) assert.ok(type(k), k);
  assert.strictEqual(s.index, 4); // 17 is in 15..19
  assert.ok(!s.typingRow);
  assert.ok(said.includes('go to scanline: 17_'), JSON.stringify(said));
  s.act('go_to_row');
  assert.ok(!type('x'), 'a letter is not a row');
  type('3');
  type('Escape');
  assert.ok(!s.typingRow);
  assert.strictEqual(s.index, 4);
  s.act('go_to_row');
  for (const k of ['4', '0', 'Enter']) type(k);
  assert.strictEqual(s.index, 4);
  assert.strictEqual(said.at(-1), 'no step shows scanline 40');
  s.goToRow('5');
  assert.strictEqual(s.index, 2);
});

// A fake clock: intervals as [period, callback], run by hand.
function fakeTimers() {
  const live = new Map();
  let next = 1;
  return {
    live,
    setInterval: (f, ms) => { live.set(next, [ms, f]); return next++; },
    clearInterval: (id) => live.delete(id),
    tick: () => [...live.values()].forEach(([, f]) => f()),
    periods: () => [...live.values()].map(([ms]) => ms),
  };
}

check('play: a step per 1/speed seconds, faster and slower while playing, stops at the end', () => {
  const timers = fakeTimers();
  const { s, shown } = stepper({ timers, speed: 2.5 });
  assert.deepStrictEqual(PLAY_SPEEDS.slice(0, 3), [0.5, 1, 2.5]);
  s.go(4);
  s.act('play');
  assert.ok(s.playing);
  assert.deepStrictEqual(timers.periods(), [400]);
  timers.tick();
  assert.strictEqual(s.index, 5);
  s.act('faster');
  assert.deepStrictEqual(timers.periods(), [200]); // 5 steps a second, one interval
  s.act('slower');
  s.act('slower');
  assert.deepStrictEqual(timers.periods(), [1000]);
  timers.tick();
  timers.tick(); // at the last step: stops
  assert.strictEqual(s.index, 6);
  assert.ok(!s.playing);
  assert.deepStrictEqual(timers.periods(), []);
  s.act('play'); // from the last step: starts again at the first
  assert.deepStrictEqual(shown.slice(-1), [0]);
  for (let i = 0; i < 20; ++i) s.act('faster');
  assert.strictEqual(s.speed, 20);
  s.act('go_to_row'); // typing a row pauses
  assert.ok(!s.playing);
});

if (process.argv[1] && import.meta.url.endsWith(process.argv[1].split('/').pop())) console.log(summary());
