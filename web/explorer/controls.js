// The explorer's player (docs/web.md): the keys of `scantrace step`, play and its speed, the rows
// a scanline step holds, the step list, `g` for a row, `?` for the keys, a link to the step. The
// keys step wherever the focus is: a dropdown used is left (blurred), and the arrow keys on one
// never change its value. Names are unique across the explorer's modules (one scope in the page).

import { controlsKey, helpTable, playerKeys } from '../player/keys.mjs';

const byId = (id) => document.getElementById(id);

// A step's title in the list and the live region: what the frame explains. The edge table's
// steps, one an entry, are numbered (the plan's k-th step; the entries are consecutive).
export function stepTitle(plan, k) {
  const step = plan[k];
  const face = step.triangle >= 0 ? ` of triangle ${step.triangle}` : '';
  if (step.kind === 'scanlines')
    return step.first_row === step.last_row ? `row ${step.last_row}${face}` : `rows ${step.first_row}..${step.last_row}${face}`;
  let entry = 1;
  while (step.kind === 'edge table' && entry <= k && plan[k - entry].kind === 'edge table' && plan[k - entry].triangle === step.triangle) ++entry;
  return `${step.kind.replace(/_/g, ' ')}${step.kind === 'edge table' ? `, entry ${entry}` : ''}${face}`;
}

// A step in a sentence, for the live region and the frame's label: its number, its title and,
// for a scanline, the row's active edges, span and the edges entering or leaving (`row`: the
// kept trace's scanline event of the step's last row).
export function stepSentence(plan, k, row) {
  let out = `Step ${k + 1} of ${plan.length}: ${stepTitle(plan, k)}.`;
  if (!row) return out;
  const at = (x) => String(Math.round(x * 1000) / 1000);
  if (row.active_edges.length) out += ` Active edges: ${row.active_edges.map((a) => `e${a.edge} at x = ${at(a.x)}`).join(', ')}.`;
  const spans = row.spans || (row.span ? [row.span] : []);
  out += spans.length ? ` Span: pixels ${spans.map((sp) => `${sp.x_begin} to ${sp.x_end - 1}`).join(', ')}.` : ' No pixel on this row.';
  if (row.entered.length) out += ` Entering: ${row.entered.map((e) => `e${e}`).join(', ')}.`;
  if (row.retired.length) out += ` Leaving: ${row.retired.map((e) => `e${e}`).join(', ')}.`;
  return out;
}

// The list of steps: rebuilt when the plan's titles change (not during a drag: the caller skips
// it there), the current one marked and scrolled into the list's view.
let listedTitles = '';
export function showStepList(plan, k) {
  const list = byId('step-list');
  const titles = plan.map((st, i) => stepTitle(plan, i));
  if (titles.join('\n') !== listedTitles) {
    listedTitles = titles.join('\n');
    list.replaceChildren(...titles.map((t) => {
      const li = document.createElement('li');
      li.textContent = t;
      return li;
    }));
  }
  const was = list.querySelector('li[aria-current]');
  const now = list.children[k];
  if (was === now) return;
  if (was) was.removeAttribute('aria-current');
  if (!now) return;
  now.setAttribute('aria-current', 'step');
  // The list's own scroll only: scrollIntoView would scroll the page's column too.
  if (now.offsetTop < list.scrollTop || now.offsetTop + now.offsetHeight > list.scrollTop + list.clientHeight)
    list.scrollTop = now.offsetTop - list.clientHeight / 2;
}

// p: { plan(), step(), setStep(k), setRows(n), link() (the address of the state), present(on) }
export function bindPlayer(p) {
  let timer = null;
  function play(on) {
    clearInterval(timer);
    timer = null;
    if (on && p.step() + 1 >= p.plan().length) p.setStep(0);
    if (on) timer = setInterval(() => (p.step() + 1 < p.plan().length ? p.setStep(p.step() + 1) : play(false)), 1000 / Number(byId('speed').value));
    byId('play').textContent = timer ? 'pause' : 'play';
    byId('play').setAttribute('aria-label', timer ? 'pause' : 'play');
  }
  byId('play').addEventListener('click', () => play(!timer));
  byId('speed').addEventListener('change', () => timer && play(true));
  byId('prev').addEventListener('click', () => p.setStep(p.step() - 1));
  byId('next').addEventListener('click', () => p.setStep(p.step() + 1));
  byId('slider').addEventListener('input', () => p.setStep(Number(byId('slider').value)));
  byId('rows').addEventListener('change', () => p.setRows(Number(byId('rows').value)));
  byId('step-list').addEventListener('click', (e) => {
    const i = [...byId('step-list').children].indexOf(e.target.closest('li'));
    if (i >= 0) p.setStep(i);
  });
  byId('toggle-list').addEventListener('click', () => {
    byId('step-list').hidden = !byId('step-list').hidden;
    byId('toggle-list').setAttribute('aria-expanded', String(!byId('step-list').hidden));
  });
  byId('help-button').addEventListener('click', () => (byId('help').hidden = !byId('help').hidden));
  // The keys' help from the key table, as every player shows it, and the buttons' titles.
  byId('help').querySelector('.keys').replaceChildren(helpTable(document, explorerKeys));
  const buttons = { prev: 'previous', play: 'play', next: 'next', 'copy-link': 'copy_link', present: 'present', 'help-button': 'help' };
  for (const [id, action] of Object.entries(buttons)) byId(id).title = explorerKeys.tip(action);
  byId('copy-link').addEventListener('click', () => copyLink(p.link()));
  bindGoto(p);
  // A dropdown used is left: the keys step again (a focused <select> takes the arrow keys).
  for (const el of document.querySelectorAll('select')) el.addEventListener('change', () => el.blur());
  window.addEventListener('keydown', (e) => {
    if (playerKey(e, p, play, () => timer)) e.preventDefault();
  });
  return { play };
}

// The link of the step shown: copied when the browser lets the page, shown to copy otherwise.
function copyLink(href) {
  const status = byId('link-status');
  const said = (t) => { status.textContent = t; };
  if (navigator.clipboard && navigator.clipboard.writeText)
    navigator.clipboard.writeText(href).then(() => said(`link copied: ${href}`), () => said(`copy this link: ${href}`));
  else said(`copy this link: ${href}`);
}

// `g`: a row asked in a small form under the player (not prompt(): it stops the page).
function bindGoto(p) {
  const form = byId('goto'), input = byId('goto-row');
  const close = () => {
    form.hidden = true;
    input.blur();
  };
  form.addEventListener('submit', (e) => {
    e.preventDefault();
    const row = Number(input.value);
    const i = p.plan().findIndex((st) => st.kind === 'scanlines' && st.first_row <= row && row <= st.last_row);
    close();
    if (i >= 0) p.setStep(i);
    else byId('link-status').textContent = `no step of row ${input.value}`;
  });
  input.addEventListener('keydown', (e) => {
    if (explorerKeys.rowKey(e.key) === 'cancel') close();
  });
}

// The explorer's actions of the players' key table (web/player/keys.json, embedded by
// make_page.mjs): the same keys as `scantrace step` and the trace page.
const explorerKeys = playerKeys(SCANTRACE_KEYS, 'explorer');

// One key: true when it was the player's. The focused control keeps its own keys (keys.mjs's
// controlsKey: text fields, a button's Space and Enter); a dropdown hands its arrows over.
function playerKey(e, p, play, playing) {
  if (controlsKey(e)) return false;
  const action = explorerKeys.action(e);
  const at = p.step();
  switch (action) {
    case 'next': p.setStep(at + 1); break;
    case 'previous': p.setStep(at - 1); break;
    case 'forward10': p.setStep(at + 10); break;
    case 'back10': p.setStep(at - 10); break;
    case 'first': p.setStep(0); break;
    case 'last': p.setStep(p.plan().length - 1); break;
    case 'play': play(!playing()); break;
    case 'go_to_row':
      byId('goto').hidden = false;
      byId('goto-row').focus();
      byId('goto-row').select();
      break;
    case 'copy_link': copyLink(p.link()); break;
    case 'help': byId('help').hidden = !byId('help').hidden; break;
    case 'present': p.present(true); break;
    case 'close':
      byId('help').hidden = true;
      p.present(false);
      break;
    default:
      return false;
  }
  return true;
}
