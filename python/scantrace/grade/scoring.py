"""Partial credit: how much of each test is right, as a fraction in [0, 1], and the rubric's points
shared out over the tests that ran (docs/grading.md, "Scoring").

A probe or an image is not all-or-nothing. Its credit is the share of its rows (fill probes) or
pixels (Gouraud probes, scenes) that are right, counted only where something should be drawn or
was drawn, so a blank background never earns points and a mistake's cost follows how much of the
picture it spoils:
  - a fill probe's row is right when its span is exactly the expected one; a row drawn where
    nothing should be, or left empty where something should be, is wrong like any other;
  - a pixel drawn where it should be but with a wrong colour (a flat colour other than the mean,
    Gouraud colours on the wrong vertices) keeps COLOUR_ONLY of its credit: the fill, the hard
    part of the assignment, is right there;
  - a crash, a timeout, a canvas of the wrong shape or a missing face gives nothing.
"""

import numpy as np

# What a pixel (or a row) drawn in the right place with a wrong colour keeps.
COLOUR_ONLY = 0.5
# What a row keeps whose span is one pixel off at either end or both (span ends rounded, a
# closed rule, the line-drawing pixels): drawn, in the right place, with its ends a pixel out.
NEAR_ROW = 0.5
# A pixel of an image agrees when every channel is within this of the reference's.
CLOSE = 1.5 / 255


def _ends(mask):
    """Per row: the first and last filled column (0, -1 where the row is empty)."""
    width = mask.shape[1]
    first = np.where(mask.any(axis=1), mask.argmax(axis=1), 0)
    last = np.where(mask.any(axis=1), width - 1 - mask[:, ::-1].argmax(axis=1), -1)
    return first, last


def fill_rows(expected, got):
    """(right, near, counted) rows of a fill probe. A row counts when either mask fills some of
    it; it is right when the two masks are equal on it, and near when it is one span whose ends
    are each at most one pixel from the expected ones (a rounding or rule mistake, not a row
    missing, added or broken)."""
    counted = expected.any(axis=1) | got.any(axis=1)
    right = counted & (expected == got).all(axis=1)
    (e0, e1), (g0, g1) = _ends(expected), _ends(got)
    one_span = got.sum(axis=1) == g1 - g0 + 1
    near = (counted & ~right & expected.any(axis=1) & got.any(axis=1) & one_span
            & (np.abs(e0 - g0) <= 1) & (np.abs(e1 - g1) <= 1))
    return int(right.sum()), int(near.sum()), int(counted.sum())


def flat_probe(expected, got, colour_ok=True):
    """A flat probe's credit: the share of its rows that are right (a near row counts NEAR_ROW),
    times COLOUR_ONLY when the colour is wrong. Nothing to draw and nothing drawn is all right."""
    right, near, counted = fill_rows(expected, got)
    if counted == 0:
        return 1.0
    return (right + NEAR_ROW * near) / counted * (1.0 if colour_ok else COLOUR_ONLY)


def gouraud_probe(expected, got, colour_right):
    """A Gouraud probe's credit, per pixel of expected | got: 1 where both fill and the colour is
    within tolerance (colour_right), COLOUR_ONLY where both fill with a wrong colour, 0 where only
    one fills."""
    union = expected | got
    if not union.any():
        return 1.0
    both = expected & got
    good = int((both & colour_right).sum())
    return (good + COLOUR_ONLY * (int(both.sum()) - good)) / int(union.sum())


def image_credit(student, reference, uncovered):
    """(credit, wrong pixels, counted pixels) of a rendered image, after the whole-image mistakes
    are undone: the share of the pixels the reference covers, or the student drew on, whose colour
    agrees with the reference (every channel within CLOSE). `uncovered`: the pixels no face of the
    reference covers."""
    # In place and counted with count_nonzero: a quarter of the time of the plain expressions
    # on a 512 x 512 image (this runs for every image test).
    d = np.subtract(student, reference)
    np.abs(d, out=d)
    error = np.maximum(d[..., 0], d[..., 1])
    wrong = np.maximum(error, d[..., 2], out=error) > CLOSE
    n_wrong = int(np.count_nonzero(wrong))
    counted = n_wrong + int(np.count_nonzero(~uncovered & ~wrong))
    if counted == 0:
        return 1.0, 0, 0
    return 1.0 - n_wrong / counted, n_wrong, counted


def allot(tests, total):
    """Shares the rubric's total over the tests that ran, in proportion to their weights, and sets
    each test's max_score and score (its fraction of that). The maxima are rounded to hundredths
    by the largest remainder (ties: the heavier test first), so they add up to `total` exactly:
    Gradescope's total never changes with the options. Deductions (weight None) keep their own
    points."""
    weighted = [t for t in tests if t.weight is not None]
    weights = sum(t.weight for t in weighted)
    if not weighted or weights <= 0:
        return tests
    exact = [t.weight * total * 100 / weights for t in weighted]
    cents = [int(e) for e in exact]
    short = round(total * 100) - sum(cents)
    # The largest remainders first; on a tie (up to rounding noise) the heavier test, then the
    # earlier one.
    order = sorted(range(len(exact)), key=lambda k: (round(cents[k] - exact[k], 6),
                                                     -weighted[k].weight, k))
    for k in order[:max(short, 0)]:
        cents[k] += 1
    for t, c in zip(weighted, cents):
        t.max_score = c / 100
        t.score = round(t.max_score * min(max(t.fraction, 0.0), 1.0), 2)
    return tests
