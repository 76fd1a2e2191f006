// The player core every page shares (the trace page, the page of pre-drawn frames, the Jupyter
// player): which step is shown, the keys of keys.json, play and its speed, going to a scanline's
// step (g), and the controls bound to it. The page only draws a step (`show`).
//
//   const s = createStepper({ count: 33, show: (i) => draw(i), rows, say: (t) => status(t) });
//   bindPlayer(s, { scope: document, keys: playerKeys(SCANTRACE_KEYS, 'trace'), slider, ... });
//
// Steps are numbered from 1 everywhere the reader sees them (the counter, the list, #step=N);
// `index` is from 0.

// Play speeds offered, in steps per second.
export const PLAY_SPEEDS = [0.5, 1, 2.5, 5, 10, 20];

// The stepping actions of keys.json's table, on a stepper.
const STEP_ACTIONS = {
  next: (s) => s.go(s.index + 1), previous: (s) => s.go(s.index - 1),
  forward10: (s) => s.go(s.index + 10), back10: (s) => s.go(s.index - 10),
  first: (s) => s.go(0), last: (s) => s.go(s.count - 1), play: (s) => s.play(!s.playing),
  faster: (s) => s.faster(), slower: (s) => s.slower(), go_to_row: (s) => s.startRow(),
};

// o: {count, show(index), rows?: [[first, last] or null per step], say?(text), speed? (steps per
// second), timers?: {setInterval, clearInterval} (tests)}.
export function createStepper(o) {
  const timers = o.timers || globalThis;
  const say = o.say || (() => {});
  const listeners = [];
  let index = 0, timer = null;
  let speed = PLAY_SPEEDS.indexOf(o.speed) >= 0 ? PLAY_SPEEDS.indexOf(o.speed) : 2;
  const changed = () => listeners.forEach((f) => f(s));
  const clamp = (i) => Math.max(0, Math.min(s.count - 1, i));
  const typed = rowTyping(() => s, go, say);

  function go(i) {
    index = clamp(i);
    o.show(index);
    changed();
  }
  function restart() {
    timers.clearInterval(timer);
    timer = timers.setInterval(() => (index + 1 < s.count ? go(index + 1) : play(false)), 1000 / PLAY_SPEEDS[speed]);
  }
  function play(on) {
    if (on === (timer !== null)) return;
    if (on) {
      if (index === s.count - 1) go(0);
      restart();
    } else {
      timers.clearInterval(timer);
      timer = null;
    }
    changed();
  }
  function setSpeed(k) {
    speed = Math.max(0, Math.min(PLAY_SPEEDS.length - 1, k));
    if (timer !== null) restart();
    say(`${PLAY_SPEEDS[speed]} steps a second`);
    changed();
  }
  const s = {
    count: o.count,
    rows: o.rows || [], // [first, last] scanline of each step, or null
    get index() { return index; },
    get playing() { return timer !== null; },
    get speed() { return PLAY_SPEEDS[speed]; },
    get typingRow() { return typed.typing; },
    go, play, goToRow: typed.goTo, typeRow: typed.type,
    faster: () => setSpeed(speed + 1),
    slower: () => setSpeed(speed - 1),
    setSpeed: (stepsPerSecond) => setSpeed(PLAY_SPEEDS.indexOf(stepsPerSecond)),
    startRow: () => { play(false); typed.start(); },
    // A new count (the steps planned again): the index kept within it.
    resize: (count, i = index) => { s.count = count; go(i); },
    onChange: (f) => listeners.push(f),
    // The action of keys.json's table, as the keys and the buttons do it; false: not a stepping one.
    act(action) {
      if (!STEP_ACTIONS[action]) return false;
      STEP_ACTIONS[action](s);
      return true;
    },
  };
  return s;
}

// g and a row: the row typed (`start`, then a key at a time: `type`), and the step showing it
// (`goTo`). `stepper()`: the stepper, whose `rows` may be planned again meanwhile.
function rowTyping(stepper, go, say) {
  let entry = null;
  // The step showing scanline `text` (the first one that does), or a message saying none does.
  function goTo(text) {
    const row = Number.parseInt(text, 10);
    const i = stepper().rows.findIndex((r) => r && r[0] <= row && row <= r[1]);
    if (!Number.isFinite(row) || i < 0) return say(`no step shows scanline ${text}`);
    go(i);
    say(`scanline ${row}`);
  }
  // A key while a row is typed after g, and its part there (keys.json's row_entry, as the
  // player's keys give it: rowKey): a character is added, erase drops the last, go goes, cancel
  // leaves the row; false for a key of no part.
  function type(role, key) {
    if (role === 'characters') entry += key;
    else if (role === 'erase') entry = entry.slice(0, -1);
    else if (role === 'go' || role === 'cancel') {
      const text = entry;
      entry = null;
      if (role === 'go' && text) goTo(text);
      else say('');
      return true;
    } else return false;
    say(`go to scanline: ${entry}_`);
    return true;
  }
  return {
    get typing() { return entry !== null; },
    start: () => { entry = ''; say('go to scanline: _'); },
    goTo, type,
  };
}
