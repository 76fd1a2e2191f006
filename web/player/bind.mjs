// A stepper (controller.mjs) bound to a page's controls: the keys of keys.json, the buttons
// (data-act="next", ...: the table's actions), the slider, the speed list, the step list, the
// help overlay and the address (#step=N). Keys are taken in the capture phase at `scope`, before
// a focused slider, list or button sees them: after a control is used, the keys still step.
import { PLAY_SPEEDS } from './controller.mjs';
import { controlsKey, helpTable } from './keys.mjs';

// o: {scope, keys (playerKeys), first (the number of step index 0, from 1), slider?, counter?
// (element) and counterText?(s), list? (element of one child per step), playButton?, speed?
// (<select>), help? (overlay element: the key table goes into its .keys element), hash? (the address follows), say?(text),
// announce? (a live region: each step's sentence, sentence?(s) or the counter's text, said by a
// screen reader), actions?
// ({name: () => ...}: the page's own, e.g. save, toggle_rows)}.
export function bindPlayer(s, o) {
  const first = o.first ?? 1, say = o.say || (() => {});
  const doc = o.scope.ownerDocument || o.scope;
  const toggleHelp = (on) => {
    if (!o.help) return;
    if (o.help.dataset.filled !== '1') {
      const box = o.help.querySelector('.keys') || o.help;
      box.insertBefore(helpTable(doc, o.keys), box.firstChild);
      o.help.dataset.filled = '1';
    }
    o.help.classList.toggle('shown', on ?? !o.help.classList.contains('shown'));
  };
  const actions = {
    help: () => toggleHelp(),
    close: () => toggleHelp(false),
    copy_link: () => copyLink(doc, say),
    ...o.actions,
  };
  const act = (name) => (actions[name] ? (actions[name](), true) : s.act(name));
  o.scope.addEventListener('keydown', (e) => {
    if (controlsKey(e)) return;
    const typing = s.typingRow;
    if (typing ? !s.typeRow(o.keys.rowKey(e.key), e.key) : !act(o.keys.action(e))) return;
    e.preventDefault();
    e.stopPropagation();
  }, true);
  for (const b of o.scope.querySelectorAll('[data-act]')) {
    // Its title and name from the key table: a button names what it does and the keys that do
    // the same (its text is an arrow).
    if (o.keys.tip(b.dataset.act)) {
      b.title = o.keys.tip(b.dataset.act);
      b.setAttribute('aria-label', b.title);
    }
    b.addEventListener('click', () => { act(b.dataset.act); b.blur(); });
  }
  if (o.slider) {
    o.slider.min = String(first);
    o.slider.max = String(first + s.count - 1);
    o.slider.addEventListener('input', () => s.go(Number(o.slider.value) - first));
    o.slider.addEventListener('change', () => o.slider.blur());
  }
  if (o.speed) bindSpeed(s, o.speed);
  if (o.help) o.help.addEventListener('click', () => toggleHelp(false));
  if (o.hash) {
    const fromHash = () => {
      const m = /step=(\d+)/.exec(doc.defaultView.location.hash);
      return m ? Number(m[1]) - first : 0;
    };
    doc.defaultView.addEventListener('hashchange', () => fromHash() !== s.index && s.go(fromHash()));
    s.initialIndex = fromHash();
  }
  s.onChange(() => update(s, o, first, doc));
  return s;
}

// The speed list's options (steps a second) and its choice.
function bindSpeed(s, select) {
  for (const v of PLAY_SPEEDS) {
    const option = select.ownerDocument.createElement('option');
    option.value = String(v);
    option.textContent = `${v} / s`;
    select.appendChild(option);
  }
  select.value = String(s.speed);
  select.addEventListener('change', () => {
    s.setSpeed(Number(select.value));
    select.blur();
  });
}

// The controls after a change: slider, counter, list, play button, speed, address.
function update(s, o, first, doc) {
  const n = first + s.index;
  if (o.slider) {
    o.slider.max = String(first + s.count - 1);
    o.slider.value = String(n);
  }
  const sentence = o.counterText ? o.counterText(s) : `step ${n} / ${first + s.count - 1}`;
  if (o.counter) o.counter.textContent = sentence;
  // Said once a step (play and speed changes leave it).
  if (o.announce && o.announce.dataset.step !== String(n)) {
    o.announce.dataset.step = String(n);
    o.announce.textContent = o.sentence ? o.sentence(s) : sentence;
  }
  if (o.list) {
    for (const el of o.list.querySelectorAll('.current')) {
      el.classList.remove('current');
      el.removeAttribute('aria-current');
    }
    const li = o.list.children[s.index];
    if (li) {
      li.classList.add('current');
      li.setAttribute('aria-current', 'step');
      li.scrollIntoView({ block: 'nearest' });
    }
  }
  if (o.playButton) o.playButton.textContent = s.playing ? 'pause' : 'play';
  if (o.speed) o.speed.value = String(s.speed);
  // The address follows the step without adding a history entry per step.
  const loc = doc.defaultView.location;
  if (o.hash && loc.hash !== `#step=${n}`) doc.defaultView.history.replaceState(null, '', `#step=${n}`);
}

// Copies the address of this step; where the clipboard is refused (file:// in some browsers),
// says the address to copy by hand.
function copyLink(doc, say) {
  const url = doc.defaultView.location.href;
  const clip = doc.defaultView.navigator.clipboard;
  const shown = () => say(`link: ${url}`);
  if (!clip) return shown();
  clip.writeText(url).then(() => say(`link copied: ${url}`), shown);
}
