// Headless Chromium driven over the DevTools protocol (node --experimental-websocket): the
// explorer's test sends real input events (mouse, keys, files) and watches the console and the
// network. Chromium is started as tests/viz/chromium_compare.hpp starts it.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

// Sends SIGKILL to the process group `pgid` until none of it is left (at most about 3 s).
async function endGroup(pgid) {
  for (let i = 0; i < 60; ++i) {
    try {
      process.kill(-pgid, 'SIGKILL');
    } catch {
      return;  // ESRCH: the group is empty
    }
    await new Promise((r) => setTimeout(r, 50));
  }
}

export async function launch() {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'scantrace-cdp-'));
  const proc = spawn('chromium', ['--headless', '--no-sandbox', '--disable-gpu', '--hide-scrollbars',
    '--force-device-scale-factor=1', '--remote-debugging-port=0', `--user-data-dir=${profile}`,
    '--window-size=1400,1000', 'about:blank'], { stdio: 'ignore', detached: true });
  // Its own process group does not get the terminal's Ctrl-C, nor dies with this process: both
  // are passed on to it (the group, helpers included) here, and undone by close().
  const endNow = () => { try { process.kill(-proc.pid, 'SIGKILL'); } catch { /* gone */ } };
  const interrupted = (signal) => {
    endNow();
    try { fs.rmSync(profile, { recursive: true, force: true, maxRetries: 20, retryDelay: 100 }); } catch { /* said nowhere: exiting */ }
    process.exit(signal === 'SIGINT' ? 130 : 143);
  };
  process.on('exit', endNow);
  process.on('SIGINT', interrupted);
  process.on('SIGTERM', interrupted);
  const portFile = path.join(profile, 'DevToolsActivePort');
  for (let i = 0; i < 300 && !fs.existsSync(portFile); ++i) await new Promise((r) => setTimeout(r, 100));
  let lines = [];
  for (let i = 0; i < 50; ++i) {
    lines = fs.readFileSync(portFile, 'utf8').split('\n');
    if (lines[1]) break;
    await new Promise((r) => setTimeout(r, 100));
  }
  const ws = new WebSocket(`ws://127.0.0.1:${lines[0]}${lines[1]}`);
  await new Promise((ok, fail) => { ws.onopen = ok; ws.onerror = fail; });
  let id = 0;
  const pending = new Map();
  const listeners = [];
  ws.onmessage = (m) => {
    const msg = JSON.parse(m.data);
    if (msg.id && pending.has(msg.id)) {
      const { ok, fail } = pending.get(msg.id);
      pending.delete(msg.id);
      if (msg.error) fail(new Error(`${msg.error.message} ${msg.error.data || ''}`));
      else ok(msg.result);
    } else if (msg.method) for (const l of listeners) l(msg);
  };
  const send = (method, params = {}, sessionId) => new Promise((ok, fail) => {
    pending.set(++id, { ok, fail });
    ws.send(JSON.stringify({ id, method, params, sessionId }));
  });
  const { targetId } = await send('Target.createTarget', { url: 'about:blank' });
  const { sessionId } = await send('Target.attachToTarget', { targetId, flatten: true });
  const page = (method, params) => send(method, params, sessionId);
  return {
    page,
    on: (f) => listeners.push(f),
    async evaluate(expression) {
      const r = await page('Runtime.evaluate', { expression, returnByValue: true, awaitPromise: true });
      if (r.exceptionDetails) throw new Error(`${expression}: ${JSON.stringify(r.exceptionDetails).slice(0, 500)}`);
      return r.result.value;
    },
    async close() {
      // The browser may end before it answers (seen under load: the socket closed first, the
      // answer never came, and Node exited with 13 on the await left unsettled): the answer, the
      // socket's close or 5 s, whichever comes first.
      let waited;
      const closed = new Promise((r) => {
        ws.addEventListener('close', r);
        waited = setTimeout(r, 5000);
      });
      try { await Promise.race([send('Browser.close'), closed]); } catch { /* gone already */ }
      clearTimeout(waited);
      ws.close();
      if (proc.exitCode === null) {
        proc.kill();
        await new Promise((r) => proc.once('exit', r));
      }
      // Chromium's helper processes (renderer, zygote, utilities) may still write into the
      // profile after the browser exits (a clean clone's CI run failed on ENOTEMPTY, and bench
      // runs left dozens of profiles behind): the browser was started as the leader of a process
      // group of its own (detached), so the whole group is ended and waited for before the
      // profile is removed. What is still in the way after that (seen at a load of 8 on 2 cores)
      // is retried a while, then said, not a failure of the checks that ran.
      await endGroup(proc.pid);
      process.off('exit', endNow);
      process.off('SIGINT', interrupted);
      process.off('SIGTERM', interrupted);
      try {
        fs.rmSync(profile, { recursive: true, force: true, maxRetries: 20, retryDelay: 100 });
      } catch (e) {
        console.log(`note: the Chromium profile ${profile} was not removed (${e.code})`);
      }
    },
  };
}

export async function until(what, f, ms = 15000) {
  const t0 = Date.now();
  for (;;) {
    const v = await f();
    if (v) return v;
    if (Date.now() - t0 > ms) throw new Error(`timed out waiting for ${what}`);
    await new Promise((r) => setTimeout(r, 50));
  }
}

// What a page must not do, collected as it happens: console errors and warnings, uncaught
// exceptions, logged errors, requests for anything but file:, data: and blob: URLs.
export function watchProblems(browser) {
  const problems = [];
  browser.on((m) => {
    if (m.method === 'Runtime.exceptionThrown')
      problems.push(`exception: ${m.params.exceptionDetails.exception?.description || m.params.exceptionDetails.text}`);
    if (m.method === 'Runtime.consoleAPICalled' && ['error', 'warning', 'assert'].includes(m.params.type))
      problems.push(`console.${m.params.type}: ${JSON.stringify(m.params.args.map((a) => a.value ?? a.description))}`);
    if (m.method === 'Log.entryAdded' && m.params.entry.level === 'error') problems.push(`log: ${m.params.entry.text}`);
    if (m.method === 'Network.requestWillBeSent' && !/^(file|data|blob):/.test(m.params.request.url))
      problems.push(`network request: ${m.params.request.url}`);
  });
  return problems;
}

// Named checks: a failure is printed and fails the run, the next check still runs.
export function checker() {
  const c = { passed: 0 };
  c.check = async (what, f) => {
    try {
      await f();
      ++c.passed;
    } catch (e) {
      console.error(`FAIL ${what}: ${e.message.split('\n').slice(0, 10).join('\n')}`);
      process.exitCode = 1;
    }
  };
  return c;
}
