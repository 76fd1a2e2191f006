"""The replay's frames from Python (Trace.frames/frame: SVG, canvas JSON, marks) and the inline
Jupyter player (Trace._repr_html_): its deck decodes to the marks the course triangle's geometry
gives (computed here from the vertices), it stays within its size bound, and in headless Chromium
it steps on keys and buttons and draws what the canvas backend draws from Frame.to_json()."""

import html
import json
import math
import pathlib
import re
import shutil
import subprocess
import sys

import numpy as np
import pytest

import scantrace
from conftest import SOURCE_DIR, run_in_chromium

V0, V1, V2 = (20, 20), (250, 80), (300, 400)
TRIANGLE = [V0, V1, V2]


@pytest.fixture(scope="module")
def trace():
    return scantrace.trace_triangle(TRIANGLE, np.eye(3))


def x_on(a, b, y):
    return a[0] + (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1])


def course_row(y):
    """Row y of the course triangle, by hand: the left edge v2-v0 (e2) and the right edge v0-v1
    (e0) above v1's row, v1-v2 (e1) from it on; the span is [ceil(left), ceil(right)) under the
    top-left rule (a centre on the right edge is not the triangle's)."""
    left = x_on(V0, V2, y)
    right = x_on(V0, V1, y) if y < V1[1] else x_on(V1, V2, y)
    return left, right, (math.ceil(left), math.ceil(right))


def two_decimals(v):
    s = f"{v:.2f}".rstrip("0").rstrip(".")
    return s


def deck_of(page):
    m = re.search(r'<script type="application/json" class="st-deck">(.*?)</script>', page, re.S)
    return json.loads(m.group(1))


def deck_marks(deck, k):
    """The marks of frame k of a deck, read in Python (not by player.js)."""
    runs = deck["frames"][k]
    ids = [i for r in range(0, len(runs), 2) for i in range(runs[r], runs[r] + runs[r + 1])]
    return [dict(m, box=tuple(m["box"])) for m in (deck["ops"][i][2] for i in ids) if m]


def test_frames_steps_and_marks_say_the_course_triangle(trace):
    f = trace.frames()
    assert repr(f) == f"<Frames: {len(f)} steps (triangles), 1280x720>"
    kinds = [s["kind"] for s in f.steps]
    assert kinds[0] == "title" and kinds[-1] == "end" and kinds.count("edge table") == 3
    rows = [s["rows"] for s in f.steps if s["kind"] == "scanlines"]
    assert rows[0][0] == 20 and rows[-1][1] == 399  # 380 rows: 20 .. 399
    k = next(i for i, s in enumerate(f.steps) if s.get("rows", (0, 0))[1] == 50)
    frame = f[k]
    assert frame.size == (1280, 720)
    left, right, span = course_row(50)
    marks = frame.marks()
    assert {m["what"] for m in frame.marks("scanline")} == {"y = 50"}
    assert {m["what"] for m in frame.marks("span")} == {f"[{span[0]}, {span[1]})"}
    labels = {m["what"] for m in frame.marks("label")}
    assert {f"x = {two_decimals(left)}", f"x = {two_decimals(right)}"} <= labels
    assert {"v0 (20, 20)", "v1 (250, 80)", "v2 (300, 400)"} <= labels
    # The canvas JSON carries the same marks, in drawing order.
    j = json.loads(frame.to_json())
    assert (j["w"], j["h"]) == (1280, 720)
    assert [dict(op[2], box=tuple(op[2]["box"])) for op in j["ops"] if op[2]] == marks
    assert trace.frame(k).marks() == marks and trace.frame(-1).marks("scanline") == []


def test_frame_svg_is_valid_svg_11(trace, tmp_path):
    svg = trace.frame(8, frame_size=(960, 540)).to_svg()
    assert svg == trace.frame(8, frame_size=(960, 540))._repr_svg_()
    assert 'width="960" height="540"' in svg
    # self-contained: images are data URIs, glyphs placed from the document's own <defs>
    assert not re.search(r'(href|src)\s*=\s*"(?!data:|#g[0-9]+")', svg)
    if not shutil.which("xmllint"):
        pytest.skip("xmllint is not installed (scripts/deps.sh installs libxml2-utils)")
    path = tmp_path / "frame.svg"
    path.write_text(svg)
    dtd = SOURCE_DIR / "tests" / "viz" / "svg11_subset.dtd"
    r = subprocess.run(["xmllint", "--noout", "--nonet", "--dtdvalid", str(dtd), str(path)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr[:2000]


def test_player_deck_decodes_to_every_scanline_of_the_triangle(trace):
    page = trace._repr_html_()
    assert len(page) <= 1_000_000  # the bound for the course triangle
    deck = deck_of(page)
    f = trace.frames(frame_size=(960, 540))
    assert len(deck["frames"]) == len(f) and deck["labels"] == [s["label"] for s in f.steps]
    scanline_steps = 0
    for k, step in enumerate(f.steps):
        marks = deck_marks(deck, k)
        assert marks == f[k].marks()  # the deck holds each frame's marks, in order
        if step["kind"] != "scanlines":
            continue
        scanline_steps += 1
        y = step["rows"][1]
        left, right, span = course_row(y)
        main = [m for m in marks if m["layer"] == 0]
        assert [m["what"] for m in main if m["kind"] == "scanline"] == [f"y = {y}"]
        if span[1] > span[0]:
            assert [m["what"] for m in main if m["kind"] == "span"] == [f"[{span[0]}, {span[1]})"]
        xs = {m["what"] for m in main if m["kind"] == "label" and m["what"].startswith("x = ")}
        assert {f"x = {two_decimals(left)}", f"x = {two_decimals(right)}"} == xs, y
    assert scanline_steps >= 30


def test_the_page_is_self_contained(trace):
    page = trace.player().html
    assert not re.search(r'(href|src)\s*=\s*"(?!data:)', page)
    assert "http://" not in page.replace('xmlns="http://www.w3.org/2000/svg"', "")
    # A script element's text cannot hold "</": the deck's only place for it is a JSON string.
    deck_text = page.split('class="st-deck">', 1)[1].split("</script>", 1)[0]
    assert "</" not in deck_text


def scene_of(n, seed=3):
    """n small random triangles over a 512 x 512 canvas (the course scene's size and count)."""
    rng = np.random.default_rng(seed)
    centres = rng.uniform(10, 500, (n, 2))
    vertices = (centres[:, None, :] + rng.uniform(-12, 12, (n, 3, 2))).reshape(-1, 2)
    faces = np.arange(3 * n).reshape(n, 3)
    return vertices, faces, rng.uniform(0, 1, (3 * n, 3)), rng.uniform(0, 100, 3 * n)


def test_a_scene_player_is_batched_within_2_mb_and_says_so():
    vertices, faces, vcolors, depth = scene_of(10000)
    t = scantrace.trace_scene(vertices, faces, vcolors, depth, shading="flat", level="triangle")
    p = t.player()
    assert p.mode == "scene" and p.max_bytes == 2_000_000
    assert len(p.html) <= 2_000_000
    assert p.full_steps == len(t.frames()) > p.steps
    assert p.note and f"instead of {p.full_steps}" in p.note and "triangles batched" in p.note
    assert html.escape(p.note) in p.html
    assert len(deck_of(p.html)["frames"]) == p.steps
    assert repr(p).startswith(f"<Player: {p.steps} steps (scene), 960x540, ")


def test_a_smaller_bound_batches_the_scanlines(trace):
    p = trace.player(max_bytes=300_000)
    assert len(p.html) <= 300_000 and p.steps < p.full_steps
    assert "scanlines batched" in p.note
    rows = [s for s in deck_of(p.html)["labels"] if s.startswith("scanlines y = ")]
    assert rows  # grouped rows: more per step than the default's
    # A bound below any replay: the first steps that fit, said so.
    q = trace.player(max_bytes=60_000)
    assert len(q.html) <= 60_000 and "the first" in q.note


def test_frame_arguments_are_checked(trace):
    with pytest.raises(ValueError, match=r"^frame_size: expected \(width, height\) from \(320, 180\)"):
        trace.frames(frame_size=(100, 100))
    with pytest.raises(ValueError, match="^mode: expected 'auto', 'triangles' or 'scene', got 'x'"):
        trace.frames(mode="x")
    with pytest.raises(ValueError, match="^max_scanline_steps: expected at least 1, got 0"):
        trace.frames(max_scanline_steps=0)
    with pytest.raises(IndexError, match=r"step 999 is out of range \(47 steps\)"):
        trace.frame(999)
    for bad in (0, -5, float("nan"), True, "1 MB"):
        with pytest.raises(ValueError, match="^max_bytes: expected a positive number of bytes"):
            trace.player(max_bytes=bad)


def test_save_writes_a_page_and_refuses_a_directory(trace, tmp_path):
    p = trace.player(max_bytes=200_000)
    p.save(tmp_path / "t.html")
    page = (tmp_path / "t.html").read_text()
    assert page.startswith("<!DOCTYPE html>") and p.html in page
    with pytest.raises(IsADirectoryError):
        p.save(tmp_path)
    assert sorted(x.name for x in tmp_path.iterdir()) == ["t.html"]  # nothing half-written


# --- headless Chromium: the page steps, and draws what Frame.to_json() draws -------------------

DRIVER = """<script>
(async function () {
  const root = document.querySelector('.scantrace-player');
  const canvas = root.querySelector('canvas');
  const ctx = canvas.getContext('2d');
  const deck = JSON.parse(root.querySelector('.st-deck').textContent);
  const REF = JSON.parse(document.getElementById('ref').textContent);
  const shown = (k) => new Promise((ok) => {
    const t = setInterval(() => { if (root.dataset.shown === String(k)) { clearInterval(t); ok(); } }, 5);
  });
  const key = (k) => root.dispatchEvent(new KeyboardEvent('keydown', {key: k, bubbles: true}));
  const out = {visits: [], strokes: 0, lines: 0, ops: 0};
  async function visit(k) {
    await shown(k);
    const a = ctx.getImageData(0, 0, canvas.width, canvas.height).data;
    const v = {shown: k, label: root.querySelector('.st-label').textContent,
               count: root.querySelector('.st-count').textContent};
    if (REF[k]) {  // the same frame through the canvas backend alone, on a canvas of its own
      const c2 = document.createElement('canvas');
      c2.width = canvas.width; c2.height = canvas.height;
      const ctx2 = c2.getContext('2d');
      await root.scantrace.drawFrame(ctx2, REF[k]);
      const b = ctx2.getImageData(0, 0, c2.width, c2.height).data;
      let sum = 0, big = 0;
      for (let i = 0; i < a.length; i += 4)
        for (let j = 0; j < 3; ++j) { const d = Math.abs(a[i + j] - b[i + j]); sum += d; if (d > 64) ++big; }
      v.mean = sum / (a.length / 4 * 3);
      v.big = big;
      // The deck's ops expanded by player.js against the canvas JSON's, number by number.
      const mine = root.scantrace.deckFrame(k).ops.filter((o) => o[0] !== 'P');
      const theirs = REF[k].ops.filter((o) => o[0] !== 'P');
      v.same_count = mine.length === theirs.length;
      for (let i = 0; i < Math.min(mine.length, theirs.length); ++i) {
        if (mine[i][0] !== theirs[i][0]) { v.kind_mismatch = i; break; }
        if (mine[i][0] === 'T') {
          const p = mine[i][6].flat(), q = theirs[i][6].flat();
          if (p.length !== q.length) { v.stroke_mismatch = i; break; }
          for (let j = 0; j < p.length; ++j) out.strokes = Math.max(out.strokes, Math.abs(p[j] - q[j]));
        } else if (mine[i][0] === 'L') {
          for (let j = 3; j < 7; ++j) out.lines = Math.max(out.lines, Math.abs(mine[i][j] - theirs[i][j]));
        }
        ++out.ops;
      }
    }
    const box = REF.v0 && REF.v0[k];
    if (box) {
      const at = ((box[1] + (box[3] >> 1)) * canvas.width + box[0] + (box[2] >> 1)) * 4;
      v.v0 = [a[at], a[at + 1], a[at + 2]];
    }
    out.visits.push(v);
  }
  await visit(0);
  key('ArrowRight'); await visit(1);
  key(' '); await visit(2);
  root.querySelector('[data-act=next]').click(); await visit(3);
  key('End'); await visit(deck.frames.length - 1);
  key('PageUp'); await visit(deck.frames.length - 11);
  key('ArrowLeft'); await visit(deck.frames.length - 12);
  key('Home'); await visit(0);
  const s = root.querySelector('input[type=range]');
  s.value = '9'; s.dispatchEvent(new Event('input')); await visit(8);  // the slider holds step numbers, from 1
  const pre = document.createElement('pre');
  pre.id = 'result';
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
})();
</script>"""


def driven_page(player_html, refs, v0_boxes):
    ref = json.dumps({**refs, "v0": v0_boxes}).replace("</", "<\\/")
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'></head><body>{player_html}"
            f"<script type='application/json' id='ref'>{ref}</script>{DRIVER}</body></html>")


@pytest.mark.skipif(not shutil.which("chromium"), reason="chromium is not installed")
def test_in_chromium_the_player_steps_and_draws_the_canvas_backends_frames(trace, tmp_path):
    p = trace.player()
    f = trace.frames(frame_size=(960, 540))
    n = len(f)
    visited = [0, 1, 2, 3, n - 1, n - 11, n - 12, 0, 8]
    refs = {k: json.loads(f[k].to_json()) for k in visited}
    v0 = {k: [m["box"] for m in f[k].marks("vertex") if m["what"] == "v0" and m["layer"] == 0]
          for k in visited}
    v0 = {k: b[0] for k, b in v0.items() if b}
    page = tmp_path / "player.html"
    page.write_text(driven_page(p.html, refs, v0))
    out = run_in_chromium(page, tmp_path)
    assert [v["shown"] for v in out["visits"]] == visited
    for v in out["visits"]:
        k = v["shown"]
        assert v["label"] == f.steps[k]["label"] and v["count"] == f"{k + 1} / {n}"
        # The player's canvas is the canvas backend's picture of the same frame (the deck's
        # strokes are exact, the canvas JSON's rounded to 1/100 px: antialiased edges differ by a
        # level or two, and a joint of the title's thick strokes by more in one pixel; a patch
        # of cells put in the wrong place or left out differs in thousands).
        assert v["same_count"] and "kind_mismatch" not in v and "stroke_mismatch" not in v
        assert v["big"] <= 10 and v["mean"] < 0.05, v
        if "v0" in v:  # vertex 0's marker is filled with its colour: red (vcolors = I)
            assert v["v0"] == [255, 0, 0], v
    # The nine visits hold about 1,770 ops (a span that fits in one zoom inset gets one inset):
    # a comparison that reached only a few of them would prove nothing.
    assert out["ops"] > 1500 and out["strokes"] <= 0.0051 and out["lines"] <= 0.0051


def test_the_replay_methods_are_the_trace_types_own():
    """Trace.frames, frame, player and _repr_html_ are defined with the type by the extension
    module, not set on it when _player.py is imported: the extension loaded alone, with
    _player.py never imported, has them."""
    code = f"""
import importlib.util, sys
spec = importlib.util.spec_from_file_location("_scantrace", {scantrace._scantrace.__file__!r})
m = importlib.util.module_from_spec(spec)
spec.loader.exec_module(m)
print(sorted(n for n in ("frames", "frame", "player", "_repr_html_") if n in vars(m.Trace)),
      "scantrace._player" in sys.modules)
"""
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert r.stdout.split() == ["['_repr_html_',", "'frame',", "'frames',", "'player']", "False"]
    source = (pathlib.Path(scantrace.__file__).parent / "_player.py").read_text()
    assert not re.search(r"^Trace\.\w+\s*=", source, re.M)
