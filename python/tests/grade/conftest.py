"""Shared pieces of the grader's tests: a correct submission in the course's Python style, the
deliberately wrong ones (each the correct one with one mistake written in), and a quick way to
grade a submission in-process (the student's code still runs in its sandbox)."""

import os
import pathlib
import textwrap

import pytest

from scantrace.grade import rubric
from scantrace.grade.grader import Options, grade
from scantrace.grade.sandbox import Limits, sandbox_problem

SHARED_DATA = pathlib.Path(os.environ.get("SCANTRACE_SHARED_DATA", "../shared/data"))
SOURCE_DIR = pathlib.Path(os.environ.get("SCANTRACE_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[3]))

# A student's correct solution, written as students of the course write it: explicit loops,
# math.ceil on the crossings, painter's order by mean depth (stable), a demo at the bottom that
# loads a hard-coded path and shows a window (which the grader must never run).
CORRECT = textwrap.dedent('''\
    import math
    import numpy as np
    import matplotlib.pyplot as plt
    from tqdm import tqdm


    def vector_interp(p1, p2, V1, V2, coord, dim):
        a, b = p1[dim - 1], p2[dim - 1]
        if a == b:  # DEGENERATE_VI
            return np.asarray(V1, dtype=float)
        t = (coord - a) / (b - a)
        return (1 - t) * np.asarray(V1, dtype=float) + t * np.asarray(V2, dtype=float)


    def _area2(v):
        return (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[2][0] - v[0][0]) * (v[1][1] - v[0][1])


    def _edges(vertices):
        edges = []
        for i in range(3):
            a, b = vertices[i], vertices[(i + 1) % 3]
            if a[1] == b[1]:
                continue
            if a[1] > b[1]:
                a, b = b, a
            edges.append((a, b))
        return edges


    def _put(img, x, y, colour):
        if 0 <= x < img.shape[1] and 0 <= y < img.shape[0]:
            img[y, x] = colour  # PUT


    def _fill(img, vertices, colour_at):
        vertices = np.asarray(vertices, dtype=float)
        if _area2(vertices) == 0:
            return img  # DEGENERATE
        ymin, ymax = vertices[:, 1].min(), vertices[:, 1].max()
        edges = _edges(vertices)
        for y in range(math.ceil(ymin), math.ceil(ymax)):  # ROWS
            xs = []
            for a, b in edges:
                if a[1] <= y < b[1]:  # ACTIVE
                    xs.append(a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))  # CROSSING
            if len(xs) < 2:
                continue
            xl, xr = min(xs), max(xs)
            for x in range(math.ceil(xl), math.ceil(xr)):  # SPAN
                _put(img, x, y, colour_at(x, y))
        return img


    def f_shading(img, vertices, vcolors):
        colour = np.mean(np.asarray(vcolors, dtype=float), axis=0)  # FLAT
        return _fill(img, vertices, lambda x, y: colour)


    def g_shading(img, vertices, vcolors):
        v = np.asarray(vertices, dtype=float)
        c = np.asarray(vcolors, dtype=float)  # COLOURS
        if _area2(v) == 0:
            return img
        m = np.array([[v[0, 0], v[1, 0], v[2, 0]], [v[0, 1], v[1, 1], v[2, 1]], [1, 1, 1]])
        inv = np.linalg.inv(m)
        return _fill(img, vertices, lambda x, y: (inv @ [x, y, 1]) @ c)


    def render_img(faces, vertices, vcolors, depth, shading):
        img = np.ones((512, 512, 3))  # CANVAS
        depth = np.asarray(depth, dtype=float).reshape(-1)
        order = np.argsort(-depth[faces].mean(axis=1), kind="stable")  # ORDER
        for k in tqdm(order):
            face = faces[k]
            if shading == "f":
                f_shading(img, vertices[face], vcolors[face])
            else:
                g_shading(img, vertices[face], vcolors[face])
        return img  # RETURN


    data = np.load("/home/student/hw1.npy", allow_pickle=True).item()
    plt.imshow(render_img(data["faces"], data["vertices"], data["vcolors"], data["depth"], "f"))
    plt.show()
    ''')

# x accumulated row by row (x += dx/dy) instead of computed: the float_drift student.
ACCUMULATED_FILL = textwrap.dedent('''\
    def _fill(img, vertices, colour_at):
        vertices = np.asarray(vertices, dtype=float)
        if _area2(vertices) == 0:
            return img
        ymin, ymax = vertices[:, 1].min(), vertices[:, 1].max()
        edges = _edges(vertices)
        x = {}
        for k, (a, b) in enumerate(edges):
            x[k] = a[0] + (math.ceil(a[1]) - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
        for y in range(math.ceil(ymin), math.ceil(ymax)):
            xs = []
            for k, (a, b) in enumerate(edges):
                if a[1] <= y < b[1]:
                    xs.append(x[k])
                    x[k] += (b[0] - a[0]) / (b[1] - a[1])
            if len(xs) < 2:
                continue
            xl, xr = min(xs), max(xs)
            for xx in range(math.ceil(xl), math.ceil(xr)):
                _put(img, xx, y, colour_at(xx, y))
        return img
    ''')


def _replace(source, old, new):
    assert source.count(old) == 1, old
    return source.replace(old, new)


def _line(marker, new):
    """Replaces the code of the line ending with `# MARKER` (keeping its indentation)."""
    def edit(source):
        lines = source.splitlines()
        hits = [i for i, l in enumerate(lines) if l.rstrip().endswith(f"# {marker}")]
        assert len(hits) == 1, marker
        i = hits[0]
        indent = lines[i][: len(lines[i]) - len(lines[i].lstrip())]
        lines[i] = indent + new
        return "\n".join(lines) + "\n"
    return edit


def _fill_function(new):
    def edit(source):
        start = source.index("def _fill(")
        end = source.index("def f_shading(")
        return source[:start] + new + "\n\n" + source[end:]
    return edit


# One mistake per cause, written in the course's style.
WRONG = {
    "span_end_rounding": [_line("SPAN", "for x in range(round(xl), round(xr)):")],
    "right_end_excluded": [_line("SPAN", "for x in range(math.ceil(xl), math.floor(xr)):")],
    "closed_rule": [_line("ROWS", "for y in range(math.ceil(ymin), math.floor(ymax) + 1):"),
                    _line("ACTIVE", "if a[1] <= y <= b[1]:"),
                    _line("SPAN", "for x in range(math.ceil(xl), math.floor(xr) + 1):")],
    "span_too_wide": [_line("SPAN", "for x in range(math.floor(xl), math.ceil(xr) + 1):")],
    "top_row_dropped": [_line("ROWS", "for y in range(math.ceil(ymin) + 1, math.ceil(ymax)):")],
    "bottom_row_dropped": [_line("ROWS",
                                 "for y in range(math.ceil(ymin), math.ceil(ymax) - 1):")],
    "edge_lag": [_line("CROSSING", "xs.append(a[0] + (max(y - 1, a[1]) - a[1]) * (b[0] - a[0])"
                                   " / (b[1] - a[1]))")],
    "float_drift": [_fill_function(ACCUMULATED_FILL)],
    # "Division by zero" on a horizontal edge, avoided by skipping the whole face.
    "horizontal_edge_skipped": [lambda s: _replace(
        s, "    if _area2(vertices) == 0:\n        return img  # DEGENERATE\n",
        "    if _area2(vertices) == 0 or len(set(vertices[:, 1].tolist())) < 3:\n"
        "        return img  # DEGENERATE\n")],
    "degenerate_drawn": [_line("DEGENERATE", "return _fill_line(img, vertices, colour_at)"),
                         lambda s: s.replace("def _fill(", textwrap.dedent('''\
                             def _fill_line(img, vertices, colour_at):
                                 for x, y in vertices:
                                     _put(img, int(x), int(y), colour_at(x, y))
                                 return img


                             def _fill(''').rstrip("\n"), 1)],
    "flat_colour_not_mean": [_line("FLAT", "colour = np.asarray(vcolors, dtype=float)[0]")],
    "gouraud_weights_permuted": [_line("COLOURS",
                                       "c = np.asarray(vcolors, dtype=float)[[1, 2, 0]]")],
    "colours_paired_after_sort": [_line("COLOURS", "c = np.asarray(vcolors, dtype=float); "
                                        "v = v[np.argsort(v[:, 1], kind='stable')]")],
    "transposed": [_line("PUT", "img[x, y] = colour")],
    "bgr": [_line("RETURN", "return img[:, :, ::-1]")],
    "background": [_line("CANVAS", "img = np.zeros((512, 512, 3))")],
    "order_reversed": [_line("ORDER", "order = np.argsort(depth[faces].mean(axis=1), "
                                      "kind='stable')")],
    "order_unstable_on_ties": [_line("ORDER", "order = np.argsort(depth[faces].mean(axis=1))"
                                              "[::-1]")],
    # Bounds checks off by one: `0 < x` (the first column and row never written) and
    # `x < W - 1` (the last ones).
    "canvas_border_clipped": [lambda s: _replace(
        s, "if 0 <= x < img.shape[1] and 0 <= y < img.shape[0]:",
        "if 0 < x < img.shape[1] and 0 < y < img.shape[0]:")],
    "vector_interp_degenerate": [lambda s: _replace(
        s, "    if a == b:  # DEGENERATE_VI\n        return np.asarray(V1, dtype=float)\n", "")],
}


# Second variants of a cause (not in WRONG, whose keys are the cause ids).
VARIANTS = {
    "canvas_border_clipped_last": [lambda s: _replace(
        s, "if 0 <= x < img.shape[1] and 0 <= y < img.shape[0]:",
        "if 0 <= x < img.shape[1] - 1 and 0 <= y < img.shape[0] - 1:")],
}


def wrong_source(cause):
    source = CORRECT
    for edit in WRONG[cause] if cause in WRONG else VARIANTS[cause]:
        source = edit(source)
    return source


@pytest.fixture(scope="session")
def sandbox_ok():
    problem = sandbox_problem()
    if problem:
        pytest.skip(problem)


def write_submission(directory, source, name="hw1.py"):
    directory.mkdir(parents=True, exist_ok=True)
    (directory / name).write_text(source)
    return directory


def quick_options(**kw):
    """The default rubric, two hidden scenes, short limits: what the tests grade with."""
    limits = kw.pop("limits", Limits(call_seconds=2.0, batch_seconds=60.0))
    return Options(rubric.load(), None, kw.pop("hidden_seed", 11), None, kw.pop("sandbox", True),
                   limits, **kw)


def grade_source(tmp_path, source, name="student", **kw):
    sub = write_submission(tmp_path / name, source)
    return grade(sub, tmp_path / f"{name}-out", quick_options(**kw))
