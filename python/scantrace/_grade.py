"""why, diff and check: the grading layer's own C++ (the code of ``scantrace why``, ``diff`` and
``check``), and the objects that hold their answers: PixelStory, DiffReport, CheckResult.

A *scene* is any of: a path (a scene file, the course's hw1.npy, a .mat or an OBJ model, as
:func:`load_scene` reads), the dict :func:`load_scene` returns, or the course's four arrays
``(faces, vertices, vcolors, depth)`` in the order of ``render_img``.
"""

import json
import os

import numpy as np

from . import _jupyter, _scantrace
from ._common import FILL_RULE, SHADING, cv_module, load_scene_file
from ._scantrace import Trace

_COURSE_SIZE = (512, 512)
_WHITE = (1.0, 1.0, 1.0)


def _scene_arrays(scene, shading):
    """The scene as keyword arguments of the C++ functions (vertices, faces, vcolors, depth, size,
    background)."""
    if isinstance(scene, (str, bytes, os.PathLike)):
        scene = load_scene_file(scene, shading)
    if isinstance(scene, dict):
        missing = [k for k in ("vertices", "faces", "vcolors", "depth") if k not in scene]
        if missing:
            raise ValueError(f"scene: the dict has no {', '.join(repr(k) for k in missing)} "
                             "(expected the dict load_scene returns)")
        return {"vertices": scene["vertices"], "faces": scene["faces"],
                "vcolors": scene["vcolors"], "depth": scene["depth"],
                "size": scene.get("size", _COURSE_SIZE),
                "background": scene.get("background", _WHITE)}
    if isinstance(scene, (tuple, list)) and len(scene) == 4:
        faces, vertices, vcolors, depth = scene
        return {"vertices": vertices, "faces": faces, "vcolors": vcolors, "depth": depth,
                "size": _COURSE_SIZE, "background": _WHITE}
    raise TypeError("scene: expected a path, the dict load_scene returns, or the course's arrays "
                    f"(faces, vertices, vcolors, depth), got {type(scene).__name__}")


class PixelStory:
    """The history of one pixel in the algorithm's terms, as ``scantrace why`` tells it.

    Fields as the JSON of ``scantrace why --json`` (trace/why_schema.json): ``pixel`` (x, y),
    ``canvas`` ({'width', 'height'}), ``shading``, ``fill_rule``, ``visibility``, ``background``,
    ``faces`` (one dict per face whose bounding box holds the pixel centre, in drawing order:
    ``face``, ``depth``, ``outcome`` — 'skipped', 'row_outside', 'left_of_span',
    'right_of_span', 'written', 'depth_rejected' — and what decided it), ``notes`` and ``final``
    ({'color', 'face'}; face None: the background). ``str(story)`` is the command's text,
    ``story.to_json()`` its JSON.
    """

    def __init__(self, json_text, text):
        self._json = json_text
        self._text = text
        d = json.loads(json_text)
        self.pixel = tuple(d["pixel"])
        self.x, self.y = self.pixel
        self.canvas = d["canvas"]
        self.shading = d["shading"]
        self.fill_rule = d["fill_rule"]
        self.visibility = d["visibility"]
        self.background = tuple(d["background"])
        self.faces = d["faces"]
        self.notes = d["notes"]
        self.final = d["final"]

    def to_json(self):
        """The JSON text of ``scantrace why --json`` (schema: trace/why_schema.json)."""
        return self._json

    def __str__(self):
        return self._text

    def __repr__(self):
        face = self.final["face"]
        who = "the background" if face is None else f"face {face}"
        return (f"<PixelStory of pixel ({self.x}, {self.y}): {len(self.faces)} face"
                f"{'' if len(self.faces) == 1 else 's'} around it, final colour "
                f"{tuple(round(c, 4) for c in self.final['color'])} from {who}>")

    def _repr_markdown_(self):
        return _jupyter.story_markdown(self)


class DiffReport:
    """Where and why an image differs from the reference render, as ``scantrace diff`` says it.

    ``agrees``: the command's exit status 0 (no differing pixel, no global mistake).
    ``verdict``: the mistakes named, first in every form of the report, in the words of the mistake
    catalogue (scantrace/grade/mistakes.json, the grader's): [{'id', 'text', 'evidence'}], id
    None for a line that names no mistake (what the image cannot tell, and what would).
    ``differing_pixels``, ``compared_pixels``, ``tolerance``; ``categories``: the count of
    differing pixels per category (boundary, near_boundary, widened, shifted, order, order_tie,
    missing_face, degenerate_drawn, colour, background, other; docs/grading.md);
    ``global_mistakes``: [{'kind', 'text', 'undone'}] (canvas size, background, transposed,
    flipped, BGR, [0, 255] floats); ``faces``: the most affected faces [{'face', 'pixels',
    'category'}]; ``missing_faces``, ``patterns``, ``colour``, ``notes``, ``examples`` as in the
    JSON report. ``diff_image()`` is the diff picture (H x W x 3 uint8: the reference in grey,
    each differing pixel in its category's colour, ``CATEGORY_COLOURS``); ``str(report)`` the
    command's Markdown, ``to_json()`` its report.json.
    """

    CATEGORY_COLOURS = dict(zip(_scantrace.DIFF_CATEGORIES, _scantrace.DIFF_CATEGORY_COLOURS))

    def __init__(self, json_text, markdown, picture):
        self._json = json_text
        self._markdown = markdown
        self._picture = picture
        d = json.loads(json_text)
        self.agrees = d["agrees"]
        self.verdict = d["verdict"]
        self.differing_pixels = d["differing_pixels"]
        self.compared_pixels = d["compared_pixels"]
        self.tolerance = d["tolerance"]
        self.canvas = d["canvas"]
        self.image_size = d["image"]
        self.categories = d["categories"]
        self.global_mistakes = d["global"]
        self.faces = d["faces"]
        self.missing_faces = d["missing_faces"]
        self.patterns = d["patterns"]
        self.colour = d["colour"]
        self.notes = d["notes"]
        self.examples = d["examples"]
        self.near_boundary = d["near_boundary"]

    def diff_image(self):
        """The diff picture as an H x W x 3 uint8 array (a copy): the reference in light grey,
        every differing pixel in the colour of its category (``DiffReport.CATEGORY_COLOURS``)."""
        return self._picture.copy()

    def to_json(self):
        """The text of ``scantrace diff -o DIR``'s report.json."""
        return self._json

    def __str__(self):
        return self._markdown

    def __repr__(self):
        if self.agrees:
            return f"<DiffReport: agrees ({self.compared_pixels} pixels compared)>"
        top = sorted(((n, c) for c, n in self.categories.items() if n), reverse=True)[:3]
        kinds = ", ".join(f"{c} {n}" for n, c in top)
        mistakes = f"; global: {', '.join(g['kind'] for g in self.global_mistakes)}" \
            if self.global_mistakes else ""
        named = "; ".join(v["text"] for v in self.verdict if v["id"])
        return (f"<DiffReport: {named + '; ' if named else ''}{self.differing_pixels} of "
                f"{self.compared_pixels} pixels differ{' (' + kinds + ')' if kinds else ''}"
                f"{mistakes}>")

    def _repr_html_(self):
        return _jupyter.diff_html(self)


class CheckResult:
    """The verdict of ``scantrace check`` on a trace: ``ok`` (also ``bool(result)``), ``problem``
    (None, or the first contradiction as 'NAME:LINE: what'), and what was looked at: ``events``,
    ``triangles``, ``edges``, ``scanlines``, ``pixels`` (None when a problem stopped the check),
    ``complete`` (the trace has its footer)."""

    def __init__(self, d):
        self.problem = d["problem"]
        self.ok = self.problem is None
        self.complete = d["complete"]
        for key in ("events", "triangles", "edges", "scanlines", "pixels"):
            setattr(self, key, d.get(key))

    def __bool__(self):
        return self.ok

    def __str__(self):
        if not self.ok:
            return self.problem
        return (f"consistent: {self.events} events, {self.triangles} triangles, {self.edges} "
                f"edge table entries, {self.scanlines} scanlines, {self.pixels} pixel events; "
                "every edge table, crossing and span agrees with the exact values"
                + ("" if self.complete else " (no footer: checked as far as the trace goes)"))

    def __repr__(self):
        return f"<CheckResult: {self}>"


def why(scene, x, y, *, shading=SHADING, fill_rule=FILL_RULE):
    """Why pixel (x, y) has its colour: ``scantrace why SCENE X Y`` as a :class:`PixelStory`.

    Every face whose bounding box holds the pixel centre, in drawing order, and what the fill did
    about the pixel. scene: a path, the dict of :func:`load_scene`, or the course's arrays
    ``(faces, vertices, vcolors, depth)``. x, y: ints on the canvas (x the column, y the row;
    numpy integers too, as ``np.nonzero`` gives them).
    Only the faces around the pixel are traced.
    """
    s = _scene_arrays(scene, shading)
    return PixelStory(*_scantrace.why(s["vertices"], s["faces"], s["vcolors"], s["depth"], x, y,
                                      shading=shading, fill_rule=fill_rule, size=s["size"],
                                      background=s["background"]))


def _image_argument(image, canvas):
    """(array, format, declared size): format "npy" for arrays and .npy files, else the image
    file's. A file goes through the command's pre-check against the scene's canvas (C++,
    grade/image_precheck.hpp): when its header declares another size, array is None and nothing
    is decoded (diff reports canvas_size from the declared size)."""
    if isinstance(image, (str, bytes, os.PathLike)):
        path = os.fsdecode(image)
        if os.path.isdir(path):
            raise ValueError(f"image: {path} is a directory, not an image file")
        with open(path, "rb") as f:
            npy = f.read(6) == b"\x93NUMPY"
        if npy:
            pixels, declared = _scantrace.read_npy_image(path, canvas)
            return pixels, "npy", declared
        return cv_module("diff of an image file (PNG, JPEG, BMP)").read_image(path, canvas)
    return image, "npy", None


def diff(scene, image, *, shading=SHADING, fill_rule=FILL_RULE, tolerance=1 / 255,
         undo=True):
    """Compares ``image`` with the reference render of ``scene``: ``scantrace diff`` as a
    :class:`DiffReport`.

    image: an H x W x 3 array, float in [0, 1] or integers 0 .. 255 of any integer dtype (uint8,
    int64, …: 8-bit values; read-only and strided arrays are fine), or a path: a .npy file, or a PNG/JPEG/BMP (decoded by the OpenCV
    part of the package). tolerance: the largest difference per channel that still counts as
    equal. undo: undo the global mistakes found before classifying the pixels (the command's
    default; ``--no-undo`` is ``undo=False``). ``report.agrees`` is the command's exit status 0.
    """
    s = _scene_arrays(scene, shading)
    pixels, image_format, declared = _image_argument(image, tuple(int(v) for v in s["size"]))
    return DiffReport(*_scantrace.diff(s["vertices"], s["faces"], s["vcolors"], s["depth"],
                                       pixels, shading=shading, fill_rule=fill_rule,
                                       size=s["size"], background=s["background"],
                                       tolerance=tolerance, undo=bool(undo),
                                       format=image_format, declared=declared))


def check(trace):
    """Verifies a trace as ``scantrace check`` does: the cheap checks of every load, and every
    edge table entry, crossing and span recomputed exactly from the snapped vertices.

    trace: a :class:`Trace` or the path of a .jsonl trace. Returns a :class:`CheckResult`; a trace
    that contradicts itself, or a file the trace reader refuses, is a result with ``ok`` False and
    the first ``problem`` ('FILE:LINE: what', the command's line), not an exception; a path that
    does not exist or is a directory raises.
    """
    if isinstance(trace, Trace):
        return CheckResult(_scantrace.check(trace, "trace"))
    if isinstance(trace, (str, bytes, os.PathLike)):
        path = os.fsdecode(trace)
        if os.path.isdir(path):
            raise ValueError(f"{path}: is a directory, not a trace file (.jsonl)")
        if not os.path.exists(path):
            raise FileNotFoundError(f"{path}: no such trace file")
        # What the load's own checks refuse is a verdict too, as `scantrace check` gives it.
        return CheckResult(_scantrace.check_file(path))
    raise TypeError(f"trace: expected a Trace or a path, got {type(trace).__name__}")
