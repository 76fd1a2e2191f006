"""What the objects show in Jupyter (and in a static export of a notebook: no kernel is needed to
look at them): Image's PNG, DiffReport's summary table and diff picture, PixelStory's Markdown.

Every output is bounded: a picture is shown at most MAX_SHOWN_PIXELS pixels large (a larger one
subsampled by a whole step, which the HTML says), a story's table at most MAX_STORY_FACES rows.
"""

import base64
import html
import os
import tempfile

import numpy as np

from . import _scantrace

MAX_SHOWN_PIXELS = 1024 * 1024
MAX_STORY_FACES = 40


def _subsampled(img):
    """img, or every step-th row and column of it so that at most MAX_SHOWN_PIXELS remain."""
    h, w = img.shape[:2]
    step = 1
    while (h // step) * (w // step) > MAX_SHOWN_PIXELS:
        step += 1
    return (img if step == 1 else img[::step, ::step]), step


def png_bytes(img):
    """The PNG of an H x W x 3 image (uint8, or float in [0, 1]), by the package's own writer
    (the command's: round(255 c) per channel)."""
    a = np.asarray(img)
    if a.dtype == np.uint8:
        a = a.astype(np.float32) / np.float32(255)
    fd, path = tempfile.mkstemp(suffix=".png")
    os.close(fd)
    try:
        _scantrace.write_png(np.clip(a, 0, 1), path)
        with open(path, "rb") as f:
            return f.read()
    finally:
        os.unlink(path)


def _img_tag(img, alt):
    shown, step = _subsampled(img)
    data = base64.b64encode(png_bytes(shown)).decode("ascii")
    note = "" if step == 1 else (f"<br><small>shown at 1/{step} ({shown.shape[1]}x"
                                 f"{shown.shape[0]} of {img.shape[1]}x{img.shape[0]})</small>")
    return (f'<img src="data:image/png;base64,{data}" alt="{html.escape(alt)}" '
            f'style="image-rendering: pixelated; max-width: 100%">{note}')


class Image:
    """An H x W x 3 image (what render() returns) that shows itself in Jupyter as a PNG.

    ``Image(scantrace.render_img(...))`` in a cell draws the render; ``.array`` is the array,
    ``.save(path)`` writes the PNG the command would (write_png). Pictures above 1024 x 1024
    pixels are shown subsampled by a whole step (the array is never changed).
    """

    def __init__(self, array):
        a = np.asarray(array)
        if a.ndim != 3 or a.shape[2] != 3:
            raise ValueError(f"array: expected an image of shape (H, W, 3), got {a.shape}")
        if a.dtype != np.uint8 and a.dtype.kind != "f":
            raise TypeError(f"array: expected a float or uint8 image, got dtype {a.dtype}")
        self.array = a

    @property
    def shape(self):
        return self.array.shape

    def save(self, path):
        """Writes the image as an 8-bit PNG (as write_png)."""
        with open(os.fspath(path), "wb") as f:
            f.write(png_bytes(self.array))

    def _repr_png_(self):
        return png_bytes(_subsampled(self.array)[0])

    def __repr__(self):
        h, w, _ = self.array.shape
        return f"<Image {w}x{h} {self.array.dtype}>"


def _color_text(c):
    return "(" + ", ".join(f"{v:.4g}" for v in c) + ")"


def story_markdown(story):
    """PixelStory as Markdown: the verdict, a table of the faces around the pixel, the notes."""
    face = story.final["face"]
    who = "the background (no face wrote it)" if face is None else f"face {face}"
    lines = [f"**Pixel ({story.x}, {story.y})** of the {story.canvas['width']}x"
             f"{story.canvas['height']} canvas ({story.shading}, {story.fill_rule}): final colour "
             f"{_color_text(story.final['color'])} from {who}.", ""]
    if story.faces:
        lines += ["| face | depth | outcome | detail |", "|---:|---:|---|---|"]
        for f in story.faces[:MAX_STORY_FACES]:
            detail = f.get("reason", "")
            if f["outcome"] == "row_outside" and "rows" in f:
                detail = f"its rows {f['rows'][0]} .. {f['rows'][1]}"
            if "span" in f:
                detail = f"span {f['span']['x_begin']} .. {f['span']['x_end'] - 1}"
            if "color" in f:
                detail += f"; colour {_color_text(f['color'])}"
            if "on_outline" in f:
                detail += f"; centre on {f['on_outline']['kind']} {f['on_outline']['index']}"
            lines.append(f"| {f['face']} | {f['depth']:.6g} | `{f['outcome']}` | "
                         f"{detail.replace('|', '/')} |")
        if len(story.faces) > MAX_STORY_FACES:
            lines.append(f"\n… {len(story.faces) - MAX_STORY_FACES} more faces: `print(story)` "
                         "tells them all.")
    else:
        lines.append("No face's bounding box holds the pixel centre.")
    lines += [""] + [f"- {n}" for n in story.notes]
    return "\n".join(lines) + "\n"


def diff_html(report):
    """DiffReport as HTML: the verdict, the global mistakes, the categories (with their colours in
    the picture) and the most affected faces, beside the diff picture."""
    e = html.escape
    if report.agrees:
        head = (f"<b>The image agrees with the reference</b> ({report.compared_pixels} pixels "
                "compared).")
    else:
        share = 100 * report.differing_pixels / max(1, report.compared_pixels)
        head = (f"<b>{report.differing_pixels} of {report.compared_pixels} pixels differ "
                f"({share:.2f} %).</b>")
    parts = ["<div>"]
    if report.verdict:  # the mistakes named, first, in the catalogue's words
        items = "".join(f"<li><b>{e(v['text'])}</b>"
                        f"{' (' + e(v['evidence']) + ')' if v['evidence'] else ''}</li>"
                        for v in report.verdict)
        parts.append(f"<p>Verdict:</p><ul>{items}</ul>")
    parts.append(f"<p>{head}</p>")
    if report.global_mistakes:
        items = "".join(f"<li><code>{e(g['kind'])}</code>: {e(g['text'])}"
                        f"{' (undone before classifying)' if g['undone'] else ''}</li>"
                        for g in report.global_mistakes)
        parts.append(f"<p>Global mistakes:</p><ul>{items}</ul>")
    rows = []
    for name, count in report.categories.items():
        r, g, b = report.CATEGORY_COLOURS[name]
        swatch = (f'<span style="display:inline-block;width:0.9em;height:0.9em;'
                  f'background:rgb({r},{g},{b})"></span>')
        rows.append(f"<tr><td>{swatch} {e(name)}</td><td style='text-align:right'>{count}</td></tr>")
    table = f"<table><tr><th>category</th><th>pixels</th></tr>{''.join(rows)}</table>"
    faces = ""
    if report.faces:
        frows = "".join(f"<tr><td>{f['face']}</td><td style='text-align:right'>{f['pixels']}"
                        f"</td><td>{e(f['category'])}</td></tr>" for f in report.faces)
        faces = ("<p>Most affected faces:</p><table><tr><th>face</th><th>pixels</th>"
                 f"<th>category</th></tr>{frows}</table>")
    picture = _img_tag(report._picture, "diff picture")
    parts.append(f'<div style="display:flex;gap:1em;align-items:flex-start">'
                 f"<div>{table}{faces}</div><div>{picture}</div></div></div>")
    return "".join(parts)
