"""A trace's replay inline in Jupyter: the Player behind Trace.player() and Trace._repr_html_ (a
trace in a cell's last line shows itself as the stepping player). Those methods, with
Trace.frames() and Trace.frame(), are defined on the type by the extension module
(python/src/frame_bindings.cpp), which calls player() and _repr_html_() here.

The frames are the replay's display lists (the frames of ``scantrace replay``, without OpenCV):
one as SVG or canvas JSON, or all of them as the player's deck (python/src/player_deck.hpp), a
self-contained HTML player drawn on a <canvas> by player.js. Nothing is loaded from the network
and no kernel is needed to step it, so it works in a static HTML export of the notebook.

Size: a player is kept within a budget (1 MB for the replay of triangles, 2 MB for a scene's
painter's algorithm, ``max_bytes`` to choose): past it, the steps are batched (more scanlines, or
more triangles, per step) and the player says so under the picture.
"""

import html
import itertools
import os
import pathlib

from . import _scantrace

TRIANGLES_BUDGET = 1_000_000
SCENE_BUDGET = 2_000_000
PLAYER_FRAME_SIZE = (960, 540)
_DEFAULT_STEPS = {"max_scanline_steps": 40, "max_scene_steps": 100}
_ids = itertools.count(1)


class Player:
    """A trace's replay as one self-contained HTML player (``trace.player()``; a Trace in a cell's
    last line shows this). Buttons, a slider and keys step it (click it first: the actions of the
    players' key table web/player/keys.json marked ``python``; ? shows them).

    ``html`` is the player (an HTML fragment, what Jupyter shows), ``save(path)`` writes it as a
    page. ``steps`` is how many steps it holds, ``full_steps`` how many the replay has with the
    default batching, ``note`` what was batched to stay within ``max_bytes`` (None when nothing
    was).
    """

    def __init__(self, trace, *, frame_size=PLAYER_FRAME_SIZE, mode="auto", max_bytes=None):
        if max_bytes is not None and (isinstance(max_bytes, bool) or
                                      not isinstance(max_bytes, (int, float)) or
                                      not max_bytes >= 1):
            raise ValueError(f"max_bytes: expected a positive number of bytes, got {max_bytes!r}")
        first = trace.frames(frame_size=frame_size, mode=mode)
        self.mode = first.mode
        self.max_bytes = int(max_bytes if max_bytes is not None else
                             TRIANGLES_BUDGET if self.mode == "triangles" else SCENE_BUDGET)
        self.full_steps = len(first)
        self.frame_size = tuple(frame_size)
        self.note = None
        self.html, self.steps = self._fit(trace, first, mode)

    def _fit(self, trace, replay, mode):
        """The player with the default steps, or with steps batched until it fits the budget
        (the deck's size is about proportional to the number of steps: a few tries suffice)."""
        options = dict(_DEFAULT_STEPS)
        key = "max_scanline_steps" if self.mode == "triangles" else "max_scene_steps"
        room = self.max_bytes - len(player_html("{}", 1, "x" * 200, self.frame_size))
        deck, _ = replay.deck()
        for _ in range(4):
            if len(deck) <= room:
                break
            smaller = max(1, int(options[key] * 0.85 * room / len(deck)))
            if smaller >= options[key]:
                break
            options[key] = smaller
            replay = trace.frames(frame_size=self.frame_size, mode=mode, **options)
            deck, _ = replay.deck()
        steps = len(replay)
        # Batching cannot shrink it further (many triangles, each with its set-up and edge
        # table): the first steps that fit.
        while len(deck) > room and steps > 1:
            steps = max(1, int(steps * 0.85 * room / len(deck)))
            deck, _ = replay.deck(0, steps - 1)
        notes = []
        if len(replay) != self.full_steps:
            what = "scanlines" if self.mode == "triangles" else "triangles"
            notes.append(f"{len(replay)} steps instead of {self.full_steps}, {what} batched")
        if steps < len(replay):
            notes.append(f"the first {steps} of them")
        if notes:
            self.note = (", ".join(notes) + f", to stay within {self.max_bytes / 1e6:g} MB "
                         "(trace.frames() and `scantrace replay` have every step)")
        return player_html(deck, steps, self.note, self.frame_size), steps

    def _repr_html_(self):
        return self.html

    def save(self, path):
        """Writes the player as a self-contained HTML page (under a temporary name, then renamed
        into place: never half-written)."""
        page = ("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>scantrace replay"
                f"</title></head><body>\n{self.html}\n</body></html>\n")
        path = pathlib.Path(os.fspath(path))
        partial = path.with_name(f".{path.name}.{os.getpid()}.partial")
        try:
            partial.write_text(page, encoding="utf-8")
            os.replace(partial, path)
        finally:
            partial.unlink(missing_ok=True)

    def __repr__(self):
        return (f"<Player: {self.steps} steps ({self.mode}), {self.frame_size[0]}x"
                f"{self.frame_size[1]}, {len(self.html) / 1e6:.2f} MB of HTML>")


def player_html(deck_json, steps, note, frame_size):
    """The player's HTML fragment: the controls, the deck as JSON, the drawing and player scripts.
    Before its script runs (or where scripts do not run: an untrusted notebook, a viewer that
    strips them) it says what it needs."""
    pid = f"scantrace-player-{os.getpid()}-{next(_ids)}"
    # "</" cannot occur in a <script> element's text: it can only be inside a JSON string here,
    # where "<\/" means the same.
    data = deck_json.replace("</", "<\\/")
    note_html = f'<div class="st-note" style="color:#555">{html.escape(note)}</div>' if note else ""
    buttons = "".join(
        f'<button data-act="{act}">{text}</button>'
        # Geometric shapes every font has (the media symbols U+23E9.. are missing from many);
        # the titles come from the key table (bind.mjs).
        for act, text in (("first", "|&#x25C0;"), ("back10", "&#x25C0;&#x25C0;"),
                          ("previous", "&#x25C0;"), ("play", "&#x25B6; play"),
                          ("next", "&#x25B6;"), ("forward10", "&#x25B6;&#x25B6;"),
                          ("last", "&#x25B6;|"), ("help", "?")))
    return f"""<div id="{pid}" class="scantrace-player" tabindex="0" style="max-width:100%;outline:none;font-family:sans-serif;font-size:13px">
<canvas width="{frame_size[0]}" height="{frame_size[1]}" style="max-width:100%;height:auto;border:1px solid #ccc;display:block"></canvas>
<div class="st-fallback">scantrace trace player ({steps} steps): it draws with JavaScript, which this viewer does not run (in Jupyter: trust the notebook, or run the cell).</div>
<div class="st-controls" style="display:none;gap:4px;align-items:center;margin-top:4px">{buttons}
<input type="range" min="0" max="{steps - 1}" value="0" style="flex:1" aria-label="step">
<select aria-label="play speed" title="play speed (+ -)"></select>
<span class="st-count" style="min-width:6em;text-align:right">1 / {steps}</span></div>
<div class="st-help" style="display:none;border:1px solid #ccc;padding:4px 8px;margin-top:4px"><div class="keys"></div></div>
<style>#{pid} .st-help.shown {{ display: block !important; }} #{pid} .st-help td:first-child {{ padding-right: 12px; font-weight: bold; }}</style>
<div class="st-label" style="margin-top:2px"></div>{note_html}
<script type="application/json" class="st-deck">{data}</script>
<script>(function () {{
{_scantrace.frame_canvas_script()}
{_scantrace.player_core_script()}
{_player_script()}
const root = document.getElementById("{pid}");
scantracePlayer(root, JSON.parse(root.querySelector(".st-deck").textContent));
}})();</script>
</div>"""


_script = None


def _player_script():
    global _script
    if _script is None:
        _script = (pathlib.Path(__file__).with_name("player.js")).read_text(encoding="utf-8")
    return _script


def player(trace, *, frame_size=PLAYER_FRAME_SIZE, mode="auto", max_bytes=None):
    """Trace.player(): the trace's replay as an inline HTML :class:`Player`."""
    return Player(trace, frame_size=frame_size, mode=mode, max_bytes=max_bytes)


def _repr_html_(trace):
    """Trace._repr_html_: the player, or why there is none."""
    try:
        return Player(trace)._repr_html_()
    except (RuntimeError, ValueError) as e:  # a canvas too large to replay, say
        return f"<p>{html.escape(repr(trace))}: no inline player ({html.escape(str(e))})</p>"
