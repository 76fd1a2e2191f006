// The trace page (docs/web.md): `replay`/`explain -o OUT.html` write the trace and this player,
// which composes each step's frame in the page with its WebAssembly module (player_api.mjs: the
// composer of the videos, and nothing the page does not call) and draws it with the canvas
// backend, sharp at any size: kilobytes of trace instead of megabytes of pre-drawn frames. The frame is fitted to the window; the step list is beside it,
// hidden until asked for. OUT.html#step=N opens at step N.

// pm: loadPlayer()'s module; cfg: {source, width, height, rows_per_step, mode, first, last, marked_pixel?}
export async function startPlayer(pm, cfg, traceText) {
  const $ = (id) => document.getElementById(id);
  const drawFrame = new Function(`${pm.canvasScript()}; return drawScantraceFrame;`)();
  const base = { width: cfg.width, height: cfg.height, rows_per_step: cfg.rows_per_step, source: cfg.source };
  if (cfg.mode) base.mode = cfg.mode;
  if (cfg.marked_pixel) base.marked_pixel = cfg.marked_pixel;
  const all = pm.open(traceText, base).steps;
  const first = Math.min(cfg.first || 0, all.length - 1);
  const last = Math.min(cfg.last ?? all.length - 1, all.length - 1);
  const steps = all.slice(first, last + 1);
  const events = traceText.split('\n').filter((l) => l).map((l) => JSON.parse(l));
  const canvas = $('frame'), ctx = canvas.getContext('2d');
  let k = 0, timer = null, drawing = Promise.resolve(), scale = 1;

  const fromHash = () => {
    const m = /step=(\d+)/.exec(location.hash);
    return m ? Math.max(0, Math.min(steps.length - 1, Number(m[1]) - 1)) : 0;
  };

  // The frame drawn at the size it is shown, in device pixels: sharp at any zoom.
  function fit() {
    const stage = $('stage');
    scale = Math.min(stage.clientWidth / cfg.width, stage.clientHeight / cfg.height);
    canvas.style.width = `${Math.floor(cfg.width * scale)}px`;
    canvas.style.height = `${Math.floor(cfg.height * scale)}px`;
  }

  function show(i) {
    k = Math.max(0, Math.min(steps.length - 1, i));
    $('slider').value = String(k);
    $('step-no').textContent = `step ${k + 1} / ${steps.length}: ${label(steps[k])}`;
    for (const [j, el] of [...$('list').children].entries()) el.classList.toggle('on', j === k);
    history.replaceState(null, '', `#step=${k + 1}`);
    const wanted = k;
    drawing = drawing.then(async () => {
      if (wanted !== k) return;
      const f = pm.frame(first + wanted);
      const dpr = window.devicePixelRatio || 1;
      canvas.width = Math.round(cfg.width * scale * dpr);
      canvas.height = Math.round(cfg.height * scale * dpr);
      ctx.setTransform(canvas.width / f.w, 0, 0, canvas.height / f.h, 0, 0);
      await drawFrame(ctx, f);
      canvas.dataset.step = String(wanted);
    });
  }

  function label(s) {
    return s.kind === 'scanlines' ? `rows ${s.first_row}..${s.last_row} of triangle ${s.triangle}`
      : s.triangle >= 0 ? `${s.kind.replace(/_/g, ' ')}, triangle ${s.triangle}` : s.kind.replace(/_/g, ' ');
  }

  function play(on) {
    clearInterval(timer);
    timer = on ? setInterval(() => (k + 1 < steps.length ? show(k + 1) : play(false)), 400) : null;
    $('play').textContent = timer ? 'pause' : 'play';
  }

  // A click on the canvas: the pixel under it and what the trace says of its row.
  canvas.addEventListener('click', (e) => {
    const s = steps[k];
    if (!s.view) return;
    const r = canvas.getBoundingClientRect();
    const u = (e.clientX - r.left) / r.width * cfg.width, v = (e.clientY - r.top) / r.height * cfg.height;
    const [vx, vy, vw, vh] = s.view;
    if (u < vx || v < vy || u >= vx + vw || v >= vy + vh) return;
    const x = Math.round((u - s.origin[0]) / s.cell), y = Math.round((v - s.origin[1]) / s.cell);
    const rows = events.filter((ev) => ev.type === 'scanline' && ev.y === y);
    const parts = rows.map((ev) => {
      const spans = ev.spans || (ev.span ? [ev.span] : []);
      const inside = spans.some((sp) => sp.x_begin <= x && x < sp.x_end);
      return `triangle ${ev.triangle}: ${spans.map((sp) => `[${sp.x_begin}, ${sp.x_end})`).join(' ') || 'no span'} → ${inside ? 'filled' : 'not filled'}`;
    });
    $('info').textContent = `pixel (${x}, ${y}): ${parts.join('; ') || 'no traced row'}`;
    $('info').dataset.pixel = `${x},${y}`;
  });

  $('slider').max = String(steps.length - 1);
  $('slider').addEventListener('input', () => show(Number($('slider').value)));
  $('prev').addEventListener('click', () => show(k - 1));
  $('next').addEventListener('click', () => show(k + 1));
  $('play').addEventListener('click', () => play(!timer));
  $('toggle-list').addEventListener('click', () => {
    $('list').hidden = !$('list').hidden;
    fit();
    show(k);
  });
  steps.forEach((s, i) => {
    const el = document.createElement('div');
    el.textContent = `${i + 1}. ${label(s)}`;
    el.addEventListener('click', () => show(i));
    $('list').appendChild(el);
  });
  window.addEventListener('keydown', (e) => {
    const key = e.key;
    if (key === 'ArrowRight' || key === 'n' || key === ' ') show(k + 1);
    else if (key === 'ArrowLeft' || key === 'p') show(k - 1);
    else if (key === 'PageDown') show(k + 10);
    else if (key === 'PageUp') show(k - 10);
    else if (key === 'Home') show(0);
    else if (key === 'End') show(steps.length - 1);
    else if (key === 'a') play(!timer);
    else return;
    e.preventDefault();
  });
  window.addEventListener('resize', () => {
    fit();
    show(k);
  });
  window.addEventListener('hashchange', () => fromHash() !== k && show(fromHash()));
  fit();
  show(fromHash());
  // Milliseconds from navigation to a working page (the test prints it; docs/performance.md).
  document.body.dataset.readyMs = performance.now().toFixed(0);
  document.body.dataset.ready = '1';
}
