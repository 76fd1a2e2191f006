"""The whole-image mistakes (transposed, flipped, BGR, background, a 0–255 scale), found and undone
by `scantrace diff`'s own C++ (grade/global_mistakes.cpp, bound as
``_scantrace.whole_image_mistakes`` and ``_scantrace.scale_255``): one implementation, with the
catalogue's one set of thresholds (mistakes.json's ``whole_image``), for `diff` and the grader."""

import re

import numpy as np

from .. import _scantrace
from .causes import CATALOGUE, Cause

# A pixel matches when no channel differs by more than this (diagnose.image_mismatch's).
MATCH = 1.5 / 255
WHITE = (1.0, 1.0, 1.0)

# What the C++ says of a mistake, for the cause's detail and confidence: "the background is
# (0.99, 0.99, 0.99) instead of (1, 1, 1) (N of M background pixels)", "... (N of M face pixels
# match after undoing it, K before)".
_COLOUR = re.compile(r"the background is (\([^)]*\)) instead of")
_SHARE = re.compile(r"\((\d+) of (\d+) (?:background|face) pixels")


def _cause(kind, text):
    share = _SHARE.search(text)
    confidence = int(share[1]) / max(int(share[2]), 1) if share else 1.0
    colour = _COLOUR.search(text) if kind == "background" else None
    return Cause(kind, confidence, text, detail=colour[1] if colour else "")


def whole_image_mistakes(student, reference, uncovered, *, background=WHITE, tolerance=MATCH):
    """student: the H x W x 3 image graded, in [0, 1] (battery.canvas); reference: the correct
    render of the same scene; uncovered: H x W, true where no face covers the pixel; background:
    the scene's. Returns (the image on the reference's canvas with the mistakes undone, float64;
    [Cause] of the catalogue's ids; diff's notes, e.g. values above 1)."""
    # As float64: integers would be read as 8-bit values (0..255 as 0..1), the grader's are not.
    found, fixed, notes = _scantrace.whole_image_mistakes(
        np.asarray(student, np.float64), np.asarray(reference, np.float64), ~np.asarray(uncovered, bool),
        background=background, tolerance=tolerance, undo=True)
    causes = [_cause(g["kind"], g["text"]) for g in found if g["kind"] in CATALOGUE]
    return fixed, causes, notes


def scale_255(value, *, background=WHITE, tolerance=MATCH):
    """A canvas brought from a 0–255 scale to [0, 1], its painted pixels only (the C++'s rule, as
    diff's scaled_255). Returns (image, the largest value when it was on that scale, else None);
    the image is `value` itself when no value is above 1."""
    if value.max() <= 1.0:
        return value, None      # nothing above 1: no scale, and no copy of the canvas
    fixed, scaled, top = _scantrace.scale_255(np.asarray(value, np.float64),
                                              background=background, tolerance=tolerance)
    return (fixed, float(top)) if scaled else (value, None)
