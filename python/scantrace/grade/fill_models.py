"""The pixels a triangle's fill writes under the correct rule and under each mistaken rule a
student may have coded: one *fill model* per geometric cause. Written here in exact arithmetic
(fractions), independently of the C++ fill; the correct model is checked against the C++ fill in
the tests.

A model maps a triangle (3 x 2 vertices [x, y]) and a canvas (height, width) to a boolean mask.
The correct rule is the course's half-open scanline rule (docs/design.md §3): rows
ceil(y_min) … ceil(y_max) − 1, and on each row the columns ceil(x_L) … ceil(x_R) − 1.
"""

import functools
import itertools
import math
from fractions import Fraction

import numpy as np


def _edges(tri):
    """The non-horizontal edges, each (top, bottom) with top[1] < bottom[1]."""
    edges = []
    for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
        if a[1] == b[1]:
            continue
        edges.append((a, b) if a[1] < b[1] else (b, a))
    return edges


def _x_at(edge, y):
    (x0, y0), (x1, y1) = edge
    return x0 + (y - y0) * (x1 - x0) / (y1 - y0)


def _exact(tri):
    return [(Fraction(float(x)), Fraction(float(y))) for x, y in tri]


def _is_degenerate(tri):
    (x0, y0), (x1, y1), (x2, y2) = tri
    return (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0) == 0


def _active(edges, y):
    """The two edges crossing row y (y_top <= y < y_bottom, the half-open rule of edges)."""
    return [e for e in edges if e[0][1] <= y < e[1][1]]


def _span_ends(tri, y, at=None):
    """(x_L, x_R) where row y crosses the triangle (exact), or None. `at(edge, y)` gives the row
    at which each edge is evaluated (edge_lag evaluates one row late)."""
    active = _active(_edges(tri), y)
    if len(active) < 2:
        return None
    xs = sorted(_x_at(e, at(e, y) if at else y) for e in active[:2])
    return xs[0], xs[1]


def _rows(tri):
    ys = [v[1] for v in tri]
    return math.ceil(min(ys)), math.ceil(max(ys))   # half-open [first, end)


def _mask(shape, spans):
    mask = np.zeros(shape, dtype=bool)
    h, w = shape
    for y, (a, b) in spans.items():
        if 0 <= y < h:
            mask[y, max(a, 0):max(min(b, w), 0)] = True
    return mask


def _floor_half_up(x):
    return math.floor(x + Fraction(1, 2))


def _spans(tri, ends, rows=None, at=None):
    """Row -> [begin, end) columns, with `ends(x_L, x_R)` the model's integer span ends."""
    tri = _exact(tri)
    if _is_degenerate(tri):
        return {}
    first, end = rows(tri) if rows else _rows(tri)
    spans = {}
    for y in range(first, end):
        crossing = _span_ends(tri, Fraction(y), at) or _closed_crossing(tri, Fraction(y))
        if crossing is not None:
            spans[y] = ends(*crossing)
    return spans


def _closed_crossing(tri, y):
    """The crossing of row y including a bottom vertex or horizontal edge (the closed rule's
    extra row), where the half-open edge test finds fewer than two edges."""
    xs = []
    for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
        lo, hi = sorted((a[1], b[1]))
        if lo <= y <= hi:
            xs += [a[0], b[0]] if a[1] == b[1] else [_x_at((a, b), y)]
    return (min(xs), max(xs)) if xs else None


def correct(tri, shape):
    """The correct fill of `tri` on a canvas of `shape`: a new mask (callers may change it), from
    one exact computation per triangle and canvas in a grading process (the grader's slowest
    Python, asked for the same probes by the tests and by the diagnosis of every submission)."""
    tri = np.asarray(tri, np.float64)
    return _correct_once(tri.tobytes(), tri.shape, tuple(shape)).copy()


@functools.lru_cache(maxsize=256)
def _correct_once(data, tri_shape, shape):
    tri = np.frombuffer(data, np.float64).reshape(tri_shape)
    return _mask(shape, _spans(tri, lambda l, r: (math.ceil(l), math.ceil(r))))


def span_end_rounding(which):
    """Span ends rounded to the nearest integer ('nearest': halves up, as int(x + 0.5); 'even':
    Python's round()), at the 'left', 'right' or 'both' ends, or truncated ('floor', as int())
    instead of ceil; with a third element "included", the rounded right end is filled too (the
    seed report's `range(round(x1), round(x2) + 1)`)."""
    def model(tri, shape):
        def ends(l, r):
            rnd = {"nearest": _floor_half_up, "even": round, "floor": math.floor}[which[1]]
            return (rnd(l) if which[0] in ("left", "both") else math.ceil(l),
                    (rnd(r) if which[0] in ("right", "both") else math.ceil(r))
                    + (len(which) > 2))
        return _mask(shape, _spans(tri, ends))
    return model


def right_end_excluded(tri, shape):
    # range(ceil(x_L), floor(x_R)): the last pixel inside the triangle is left out.
    return _mask(shape, _spans(tri, lambda l, r: (math.ceil(l), math.floor(r))))


def _closed_rows(tri):
    ys = [v[1] for v in tri]
    return math.ceil(min(ys)), math.floor(max(ys)) + 1


def closed_rule(tri, shape):
    # Every pixel whose centre is inside or on any edge: x_L <= x <= x_R, y_min <= y <= y_max.
    return _mask(shape, _spans(tri, lambda l, r: (math.ceil(l), math.floor(r) + 1),
                               rows=_closed_rows))


def span_too_wide(tri, shape):
    # The pixels a line drawing of the two edges lights, used as span ends: floor(x_L) … ceil(x_R).
    return _mask(shape, _spans(tri, lambda l, r: (math.floor(l), math.ceil(r) + 1)))


def top_row_dropped(tri, shape):
    return _mask(shape, _spans(tri, lambda l, r: (math.ceil(l), math.ceil(r)),
                               rows=lambda t: (_rows(t)[0] + 1, _rows(t)[1])))


def bottom_row_dropped(tri, shape):
    return _mask(shape, _spans(tri, lambda l, r: (math.ceil(l), math.ceil(r)),
                               rows=lambda t: (_rows(t)[0], _rows(t)[1] - 1)))


def edge_lag(tri, shape):
    # x of each edge updated after the row is drawn: row y uses the crossing of row y − 1 (the
    # edge's own first row uses its start).
    def at(edge, y):
        return max(y - 1, math.ceil(edge[0][1]))
    return _mask(shape, _spans(tri, lambda l, r: (math.ceil(l), math.ceil(r)), at=at))


def float_drift(tri, shape):
    """x accumulated as x += dx/dy in float64 from each edge's first row: on rows where the exact
    crossing is a whole number the sum is a hair off, and ceil() moves the span end by one.
    (The composition with only the edge stepping off: _stepped_crossings accumulates.)"""
    return Composer(tri, shape).mask((None, None, ("float_drift", ""), None))


def horizontal_edge_skipped(tri, shape):
    """A face with a horizontal edge is not drawn at all (a guard against dy = 0 in the slope
    returning early, or a `ZeroDivisionError` caught around the whole face)."""
    ex = _exact(tri)
    if any(a[1] == b[1] for a, b in ((ex[0], ex[1]), (ex[1], ex[2]), (ex[2], ex[0]))):
        return np.zeros(shape, dtype=bool)
    return correct(tri, shape)


def canvas_border_clipped(which):
    """The correct fill behind a bounds check off by one: the canvas's first column and row
    ('first': `0 < x`, `0 < y`) or its last ones ('last': `x < W − 1`, `y < H − 1`) never
    written (only the border probes fill them)."""
    def model(tri, shape):
        mask = correct(tri, shape)
        k = 0 if which == "first" else -1
        mask[k, :] = False
        mask[:, k] = False
        return mask
    return model


def degenerate(tri):
    return _is_degenerate(_exact(tri))


INCLUDED_NEAREST = "nearest at both ends, the right end included"
INCLUDED_EVEN = "rounded with round() (halves to even) at both ends, the right end included"
# The geometric causes and their models (span_end_rounding has one model per variant).
MODELS = {
    ("span_end_rounding", "nearest at both ends"): span_end_rounding(("both", "nearest")),
    ("span_end_rounding", "nearest at the left end"): span_end_rounding(("left", "nearest")),
    ("span_end_rounding", "nearest at the right end"): span_end_rounding(("right", "nearest")),
    ("span_end_rounding", "rounded with round() (halves to even) at both ends"):
        span_end_rounding(("both", "even")),
    ("span_end_rounding", "truncated (floor) at both ends"): span_end_rounding(("both", "floor")),
    ("span_end_rounding", INCLUDED_NEAREST): span_end_rounding(("both", "nearest", "included")),
    ("span_end_rounding", INCLUDED_EVEN): span_end_rounding(("both", "even", "included")),
    ("right_end_excluded", ""): right_end_excluded,
    ("closed_rule", ""): closed_rule,
    ("span_too_wide", ""): span_too_wide,
    ("top_row_dropped", ""): top_row_dropped,
    ("bottom_row_dropped", ""): bottom_row_dropped,
    ("edge_lag", ""): edge_lag,
    ("float_drift", ""): float_drift,
    ("horizontal_edge_skipped", ""): horizontal_edge_skipped,
    ("canvas_border_clipped", "first column and row (x = 0, y = 0)"):
        canvas_border_clipped("first"),
    ("canvas_border_clipped", "last column and row (x = W − 1, y = H − 1)"):
        canvas_border_clipped("last"),
}


def row_spans(mask):
    """Row -> list of [begin, end) runs of a mask (one run for a convex fill)."""
    spans = {}
    for y in np.flatnonzero(mask.any(axis=1)):
        row = np.concatenate(([False], mask[y], [False]))
        d = np.flatnonzero(np.diff(row.astype(np.int8)))
        spans[int(y)] = [(int(a), int(b)) for a, b in zip(d[::2], d[1::2])]
    return spans


# ---- composed models -------------------------------------------------------------------------
# Real fills carry several of these mistakes at once. A composed model picks one choice on each
# axis (None: the correct one), keyed by the cause it names: span-end rule × row range × edge
# stepping × vertex rounding. The one-mistake models above are the compositions with one axis
# off (closed_rule is its span ends and its rows: one cause).
SPAN_ENDS = {
    None: lambda l, r: (math.ceil(l), math.ceil(r)),
    ("span_end_rounding", "nearest at both ends"): lambda l, r: (_floor_half_up(l),
                                                                 _floor_half_up(r)),
    ("span_end_rounding", "nearest at the left end"): lambda l, r: (_floor_half_up(l),
                                                                    math.ceil(r)),
    ("span_end_rounding", "nearest at the right end"): lambda l, r: (math.ceil(l),
                                                                     _floor_half_up(r)),
    ("span_end_rounding", "rounded with round() (halves to even) at both ends"):
        lambda l, r: (round(l), round(r)),
    ("span_end_rounding", "truncated (floor) at both ends"):
        lambda l, r: (math.floor(l), math.floor(r)),
    ("span_end_rounding", INCLUDED_NEAREST): lambda l, r: (_floor_half_up(l),
                                                           _floor_half_up(r) + 1),
    ("span_end_rounding", INCLUDED_EVEN): lambda l, r: (round(l), round(r) + 1),
    ("right_end_excluded", ""): lambda l, r: (math.ceil(l), math.floor(r)),
    ("span_too_wide", ""): lambda l, r: (math.floor(l), math.ceil(r) + 1),
    ("closed_rule", ""): lambda l, r: (math.ceil(l), math.floor(r) + 1),
}
ROW_RANGES = {
    None: _rows,
    ("top_row_dropped", ""): lambda t: (_rows(t)[0] + 1, _rows(t)[1]),
    ("bottom_row_dropped", ""): lambda t: (_rows(t)[0], _rows(t)[1] - 1),
    ("closed_rule", ""): _closed_rows,
}
EDGE_STEPPING = (None, ("edge_lag", ""), ("float_drift", ""))
# int(round(x)) on each vertex before an exact fill: no change on the course's integer vertices.
VERTEX_ROUNDING = (None, ("vertices_rounded", "to the nearest integer (round())"))
COMPOSITIONS = [c for c in itertools.product(SPAN_ENDS, ROW_RANGES, EDGE_STEPPING,
                                             VERTEX_ROUNDING) if any(c)]


def causes_of(composition):
    """The (cause id, variant) pairs a composition names, each once, in axis order."""
    return list(dict.fromkeys(k for k in composition if k is not None))


def _stepped_crossings(tri, stepping):
    """Row -> (x_L, x_R) on every row with two active edges, each edge's x found exactly
    (None), one row late (edge_lag) or accumulated in float64 from its first row (float_drift)."""
    first, end = _rows(tri)
    if stepping is None or stepping[0] == "edge_lag":
        at = None if stepping is None else (lambda e, y: max(y - 1, math.ceil(e[0][1])))
        return {y: c for y in range(first, end)
                if (c := _span_ends(tri, Fraction(y), at)) is not None}
    accumulated = {}
    for e in _edges(tri):
        (x0, y0), (x1, y1) = e
        step = float(x1 - x0) / float(y1 - y0)
        x = float(x0) + (math.ceil(y0) - float(y0)) * step
        for y in range(math.ceil(y0), math.ceil(y1)):
            accumulated[(e, y)] = x
            x += step
    crossings = {}
    for y in range(first, end):
        active = _active(_edges(tri), Fraction(y))
        if len(active) >= 2:
            crossings[y] = tuple(sorted(accumulated[(e, y)] for e in active[:2]))
    return crossings


class Composer:
    """The rows a composed model fills on one triangle and canvas, as {row: [(begin, end)]}
    clipped to the canvas (row_spans' form), the crossings shared between the compositions."""

    def __init__(self, tri, shape):
        self.tri, self.shape, self.cache = tri, shape, {}

    def _geometry(self, stepping, rounding):
        key = (stepping, rounding)
        if key not in self.cache:
            tri = _exact(self.tri)
            if rounding is not None:
                tri = [(Fraction(round(x)), Fraction(round(y))) for x, y in tri]
            self.cache[key] = (tri, None if _is_degenerate(tri)
                               else _stepped_crossings(tri, stepping))
        return self.cache[key]

    def rows(self, composition):
        span, row_range, stepping, rounding = composition
        tri, crossings = self._geometry(stepping, rounding)
        if crossings is None:
            return {}
        h, w = self.shape
        first, end = ROW_RANGES[row_range](tri)
        spans = {}
        for y in range(max(first, 0), min(end, h)):
            crossing = crossings.get(y) or _closed_crossing(tri, Fraction(y))
            if crossing is None:
                continue
            a, b = SPAN_ENDS[span](*crossing)
            a, b = max(a, 0), min(b, w)
            if b > a:
                spans[y] = [(a, b)]
        return spans

    def mask(self, composition):
        mask = np.zeros(self.shape, dtype=bool)
        for y, [(a, b)] in self.rows(composition).items():
            mask[y, a:b] = True
        return mask
