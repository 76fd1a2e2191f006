#include "viz/html_player_page.hpp"

namespace scantrace::viz {

// Why plain script and no framework: the page must work offline from a single file, in any
// browser of the last years, and stay small next to the frames it carries.
std::string_view html_player_page() {
  return R"HTML(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="scantrace">
<title>@TITLE@</title>
<style>
  html, body { margin: 0; background: #1b1d22; color: #e6e6e6;
               font: 14px/1.4 system-ui, -apple-system, "Segoe UI", sans-serif; }
  #app { display: flex; gap: 12px; padding: 8px; align-items: flex-start; }
  /* The frame shrinks to the window beside the step list (never hidden behind it), keeping its
     proportions; it is never enlarged past its own size. */
  #main { flex: 1 1 auto; min-width: 0; }
  #frame { display: block; max-width: 100%; height: auto; image-rendering: pixelated;
           background: #000; }
  #controls { display: flex; gap: 6px; align-items: center; margin-top: 6px; }
  #controls button { background: #2d3038; color: #e6e6e6; border: 1px solid #4a4e58;
                     border-radius: 4px; padding: 3px 9px; font: inherit; cursor: pointer; }
  #controls button:hover { background: #3a3e48; }
  #slider { flex: 1; min-width: 200px; }
  #counter { font-variant-numeric: tabular-nums; min-width: 9em; text-align: right; }
  #hint { margin-top: 4px; color: #a8abb3; font-size: 13px; }
  #status { color: #ffd479; min-height: 1.4em; font-size: 13px; }
  #list { flex: 0 0 220px; max-height: calc(100vh - 24px); overflow: auto; margin: 0;
          padding: 0 0 0 3.2em; font-size: 13px; }
  #list li { cursor: pointer; padding: 1px 4px; border-radius: 3px; }
  #list li:hover { background: #2d3038; }
  #list li.current { background: #3d5a80; color: #fff; }
  #help { position: fixed; inset: 0; display: none; align-items: center; justify-content: center;
          background: rgba(0, 0, 0, 0.6); }
  #help.shown { display: flex; }
  #help div { background: #24272e; border: 1px solid #4a4e58; border-radius: 6px;
              padding: 12px 20px; }
  #help td:first-child { padding-right: 16px; color: #ffd479; white-space: nowrap; }
</style>
</head>
<body>
<div id="app">
  <div id="main">
    <img id="frame" alt="the frame of the current step">
    <div id="controls">
      <button id="first" title="first step (Home)">|&#x25C0;</button>
      <button id="back10" title="10 steps back (PgUp)">&#x2212;10</button>
      <button id="prev" title="previous step (&#x2190;, p)">&#x25C0;</button>
      <button id="play" title="play / pause (a)">play</button>
      <button id="next" title="next step (&#x2192;, space, n)">&#x25B6;</button>
      <button id="fwd10" title="10 steps on (PgDn)">+10</button>
      <button id="last" title="last step (End)">&#x25B6;|</button>
      <input id="slider" type="range" min="1" max="1" value="1" aria-label="step">
      <span id="counter"></span>
    </div>
    <div id="hint">&#x2190; &#x2192; step &#xB7; PgUp PgDn &#xB1;10 &#xB7; Home End &#xB7;
      g <i>row</i> Enter: go to a scanline &#xB7; a play &#xB7; s save frame &#xB7; ? all keys</div>
    <div id="status"></div>
  </div>
  <ol id="list"></ol>
</div>
<div id="help"><div>
  <table>
    <tr><td>&#x2192; / space / n</td><td>next step</td></tr>
    <tr><td>&#x2190; / p</td><td>previous step</td></tr>
    <tr><td>PgDn / PgUp</td><td>10 steps on / back</td></tr>
    <tr><td>Home / End</td><td>first / last step</td></tr>
    <tr><td>g, a row, Enter</td><td>the step of that scanline</td></tr>
    <tr><td>a</td><td>play / pause</td></tr>
    <tr><td>s</td><td>save the current frame</td></tr>
    <tr><td>r</td><td>one step per scanline: in the window (scantrace step), this page holds
      the replay's steps</td></tr>
    <tr><td>?</td><td>this help (Esc closes)</td></tr>
  </table>
  <p>The address follows the step: copy it to send a link to this step.</p>
</div></div>
<script>
"use strict";
const DATA = @DATA@;
(function () {
  const n = DATA.frames.length, base = DATA.first;  // steps base .. base + n - 1
  const img = document.getElementById("frame"), slider = document.getElementById("slider");
  const counter = document.getElementById("counter"), status = document.getElementById("status");
  const list = document.getElementById("list"), help = document.getElementById("help");
  const playButton = document.getElementById("play");
  img.width = DATA.width; img.height = DATA.height;
  slider.min = base; slider.max = base + n - 1;
  list.start = base;
  const items = DATA.labels.map(function (label, i) {
    const li = document.createElement("li");
    li.textContent = label;
    li.addEventListener("click", function () { show(base + i); });
    list.appendChild(li);
    return li;
  });
  let current = -1, timer = null, rowEntry = null;

  // A frame as an address the <img> can show. Gzipped frames (the SVG page, viz/step_page.hpp)
  // are inflated when first shown, not all at load: the page opens at once whatever its length.
  const urls = DATA.gzip ? [] : DATA.frames;
  function frameUrl(i) {
    if (urls[i]) return Promise.resolve(urls[i]);
    const bytes = Uint8Array.from(atob(DATA.frames[i]), function (c) { return c.charCodeAt(0); });
    const inflated = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"));
    return new Response(inflated).arrayBuffer().then(function (b) {
      urls[i] = URL.createObjectURL(new Blob([b], { type: DATA.mime }));
      return urls[i];
    });
  }
  function clamp(step) { return Math.min(base + n - 1, Math.max(base, step)); }
  function say(text) { status.textContent = text; }
  function show(step) {
    step = clamp(step);
    if (step === current) return;
    if (current >= 0) items[current - base].classList.remove("current");
    current = step;
    const wanted = step;
    frameUrl(step - base).then(function (url) { if (current === wanted) img.src = url; },
                                function (e) { say("cannot show step " + wanted + ": " + e); });
    slider.value = step;
    counter.textContent = "step " + step + " / " + DATA.total;
    const li = items[step - base];
    li.classList.add("current");
    li.scrollIntoView({ block: "nearest" });
    // The address follows the step without adding a history entry per step.
    if (location.hash !== "#step=" + step) history.replaceState(null, "", "#step=" + step);
    document.title = DATA.title + " - step " + step;
  }
  function fromHash() {
    const m = /step=(\d+)/.exec(location.hash);
    return m ? parseInt(m[1], 10) : base;
  }
  function play(on) {
    if (on === (timer !== null)) return;
    if (on) {
      if (current === base + n - 1) show(base);
      timer = setInterval(function () {
        if (current >= base + n - 1) play(false); else show(current + 1);
      }, 1000 / DATA.fps);
    } else {
      clearInterval(timer);
      timer = null;
    }
    playButton.textContent = on ? "pause" : "play";
  }
  function save() {
    if (!urls[current - base]) { say("step " + current + " is still being drawn"); return; }
    const a = document.createElement("a");
    a.href = urls[current - base];
    a.download = "step_" + String(current).padStart(5, "0") + "." + DATA.extension;
    document.body.appendChild(a);
    a.click();
    a.remove();
    say("saved " + a.download);
  }
  function goToRow(text) {
    const row = parseInt(text, 10);
    const i = DATA.rows.findIndex(function (r) { return r && r[0] <= row && row <= r[1]; });
    if (i < 0) { say("no step shows scanline " + text); return; }
    show(base + i);
    say("scanline " + row);
  }

  document.addEventListener("keydown", function (e) {
    if (e.ctrlKey || e.altKey || e.metaKey) return;
    const k = e.key;
    if (rowEntry !== null) {  // after g: digits, Backspace, Enter, Esc
      if (/^[0-9-]$/.test(k)) rowEntry += k;
      else if (k === "Backspace") rowEntry = rowEntry.slice(0, -1);
      else if (k === "Enter") { const t = rowEntry; rowEntry = null; if (t) goToRow(t); else say(""); e.preventDefault(); return; }
      else if (k === "Escape") { rowEntry = null; say(""); e.preventDefault(); return; }
      else return;
      say("go to scanline: " + rowEntry + "_");
      e.preventDefault();
      return;
    }
    let handled = true;
    switch (k) {
      case "ArrowRight": case " ": case "n": show(current + 1); break;
      case "ArrowLeft": case "p": show(current - 1); break;
      case "PageDown": show(current + 10); break;
      case "PageUp": show(current - 10); break;
      case "Home": show(base); break;
      case "End": show(base + n - 1); break;
      case "g": rowEntry = ""; say("go to scanline: _"); break;
      case "a": play(timer === null); break;
      case "s": save(); break;
      case "r": say("one step per scanline is in the window: scantrace step " + DATA.source + " (then r)"); break;
      case "?": help.classList.toggle("shown"); break;
      case "Escape": help.classList.remove("shown"); break;
      default: handled = false;
    }
    // The page's own keys win over the slider's and the page scroll's defaults.
    if (handled) e.preventDefault();
  }, true);
  slider.addEventListener("input", function () { show(parseInt(slider.value, 10)); });
  document.getElementById("first").onclick = function () { show(base); };
  document.getElementById("back10").onclick = function () { show(current - 10); };
  document.getElementById("prev").onclick = function () { show(current - 1); };
  document.getElementById("next").onclick = function () { show(current + 1); };
  document.getElementById("fwd10").onclick = function () { show(current + 10); };
  document.getElementById("last").onclick = function () { show(base + n - 1); };
  playButton.onclick = function () { play(timer === null); };
  help.onclick = function () { help.classList.remove("shown"); };
  window.addEventListener("hashchange", function () { show(fromHash()); });
  show(fromHash());
})();
</script>
</body>
</html>
)HTML";
}

}  // namespace scantrace::viz
