// The players' key table (keys.json) as the pages use it: a key event's action and the help
// overlay's rows. One table for every player, the `scantrace step` window included
// (cli/player_keys.cpp reads the same file), so a key means the same thing everywhere.
//
//   const keys = playerKeys(SCANTRACE_KEYS, 'trace');
//   keys.action(event)   // 'next', 'go_to_row', ... or null
//   keys.help()          // [[label, help], ...] for this player
//   keys.hint(['next', 'help'])   // '→ / space / n next step · ? these keys (Esc closes)'

// `table`: keys.json's object; `player`: 'trace', 'step', 'python' or 'explorer' (the actions it has).
export function playerKeys(table, player) {
  const actions = table.actions.filter((a) => a.in.includes(player));
  const byKey = new Map();
  for (const a of actions) for (const k of a.keys) if (!byKey.has(k)) byKey.set(k, a.action);
  // A key's part in typing a row after g: 'characters', 'go', 'erase', 'cancel' (table.row_entry).
  const rowRoles = new Map(Object.entries(table.row_entry).flatMap(([role, keys]) => keys.map((k) => [k, role])));
  return {
    // The part of key name `key` while a row is typed, or null: the key does nothing then.
    rowKey: (key) => rowRoles.get(key) || null,
    // The action of a keydown event, or null: keys with Ctrl, Alt or Meta are the browser's.
    action: (e) => (e.ctrlKey || e.altKey || e.metaKey ? null : byKey.get(e.key) || null),
    help: () => actions.filter((a) => a.action !== 'close').map((a) => [a.label, a.help]),
    has: (action) => actions.some((a) => a.action === action),
    // A button's title: its action's help line and keys ('' when this player has no such action).
    tip: (name) => actions.filter((a) => a.action === name).map((a) => `${a.help} (${a.label})`).join(''),
    // A one-line hint: the named actions this player has, each as its label and help line.
    hint: (names) => actions.filter((a) => names.includes(a.action)).map((a) => `${a.label} ${a.help}`).join(' \u00b7 '),
  };
}

// The help overlay's table: one row per action of this player, built from the key table.
export function helpTable(doc, keys) {
  const table = doc.createElement('table');
  for (const [label, help] of keys.help()) {
    const row = table.insertRow();
    row.insertCell().textContent = label;
    row.insertCell().textContent = help;
  }
  return table;
}

// Whether a key is the focused control's own: a text field's keys, Space and Enter on a button
// (a keyboard's click). A list's arrows are the player's, and ↑ ↓ nobody's: their default would
// change its value unseen (the list is left, so the next keys step).
export function controlsKey(e) {
  const t = e.target, k = e.key;
  if (t.tagName === 'INPUT' && ['text', 'number', 'search'].includes(t.type)) return true;
  if ((t.tagName === 'BUTTON' || t.tagName === 'SUMMARY') && (k === ' ' || k === 'Enter')) return true;
  if (t.tagName === 'SELECT' && k.startsWith('Arrow')) {
    t.blur();
    if (k === 'ArrowUp' || k === 'ArrowDown') e.preventDefault();
  }
  return false;
}
