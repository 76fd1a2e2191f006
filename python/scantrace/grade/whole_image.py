"""The whole-image mistakes (transposed, flipped, BGR, background, a 0-255 scale) found by
`scantrace diff`'s own C++ (grade/global_mistakes.cpp, bound as
``_scantrace.whole_image_mistakes``): one implementation, with the catalogue's one set of
thresholds (mistakes.json's ``whole_image``), for `diff` and the grader. diagnose.diagnose_image
names transposed, BGR and background in numpy with the same thresholds; this is the call that
replaces it (python/tests/grade/test_whole_image_agreement.py holds the three to one answer).
"""

import numpy as np

from .. import _scantrace
from .causes import CATALOGUE, Cause

# A pixel matches when no channel differs by more than this (diagnose.image_mismatch's).
MATCH = 1.5 / 255


def whole_image_mistakes(student, reference, uncovered, *, background=(1.0, 1.0, 1.0),
                         tolerance=MATCH):
    """student: the H x W x 3 image graded (float, or integers 0..255); reference: the correct
    render of the same scene; uncovered: H x W, true where no face covers the pixel; background:
    the scene's. Returns (the image on the reference's canvas with the mistakes undone, float64;
    [Cause] of the catalogue's ids; diff's notes, e.g. values above 1)."""
    found, fixed, notes = _scantrace.whole_image_mistakes(
        student, np.asarray(reference, np.float64), ~np.asarray(uncovered, bool),
        background=background, tolerance=tolerance, undo=True)
    causes = [Cause(g["kind"], 1.0, g["text"]) for g in found if g["kind"] in CATALOGUE]
    return fixed, causes, notes
