"""A student's pytest file: trace my triangle and check what the scanline fill did.

Run it with: PYTHONPATH=build/python python3 -m pytest examples/python/test_my_triangle.py
"""

import math

import numpy as np
import pytest

import scantrace

# My triangle: red, green and blue corners.
V = np.array([[10.0, 5.0], [60.0, 25.0], [25.0, 50.0]])
C = np.eye(3)


def x_on_edge(a, b, y):
    """Where the edge a-b crosses row y (my own formula, not scantrace's)."""
    return a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])


def test_active_edges_on_row_30():
    t = scantrace.trace_triangle(V, C)
    row = t.scanline(0, 30)
    # Row 30 is below vertex 1 (y = 25): the active edges are v1-v2 on the right and v2-v0 on
    # the left.
    xs = sorted(e.x for e in row.active_edges)
    assert xs == pytest.approx(sorted([x_on_edge(V[2], V[0], 30), x_on_edge(V[1], V[2], 30)]))
    assert sorted(e.edge for e in row.active_edges) == [1, 2]


def test_span_of_row_30():
    t = scantrace.trace_triangle(V, C)
    left, right = x_on_edge(V[2], V[0], 30), x_on_edge(V[1], V[2], 30)
    span = t.scanline(0, 30).span
    # Top-left rule: the first pixel is ceil(x_left), the span ends before ceil(x_right).
    assert (span.x_begin, span.x_end) == (math.ceil(left), math.ceil(right))


def test_colour_of_a_pixel():
    t = scantrace.trace_triangle(V, C, shading="gouraud")
    x, y = 30, 30
    # The barycentric weights of pixel (30, 30) are the colour of a Gouraud fill with RGB corners.
    m = np.array([[V[0, 0], V[1, 0], V[2, 0]], [V[0, 1], V[1, 1], V[2, 1]], [1, 1, 1]])
    weights = np.linalg.solve(m, [x, y, 1])
    assert t.pixel_history(x, y).final().color == pytest.approx(weights, abs=1e-4)
    assert t.image[y, x] == pytest.approx(weights, abs=1e-4)


def naive_flat_fill(img, vertices, vcolors):
    """My own fill: every pixel centre strictly inside, or on a top or left edge (the top-left
    rule), gets the mean colour. Slow but obviously right."""
    (x0, y0), (x1, y1), (x2, y2) = vertices
    area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    if area == 0:
        return img
    if area < 0:  # make the vertex order clockwise on screen (y down)
        (x1, y1), (x2, y2) = (x2, y2), (x1, y1)
    color = np.mean(vcolors, axis=0)
    ys, xs = np.mgrid[0:img.shape[0], 0:img.shape[1]]
    inside = np.ones(xs.shape, bool)
    for (ax, ay), (bx, by) in (((x0, y0), (x1, y1)), ((x1, y1), (x2, y2)), ((x2, y2), (x0, y0))):
        e = (bx - ax) * (ys - ay) - (by - ay) * (xs - ax)
        # An edge going right along the top (dy = 0, dx > 0) or going up (dy < 0) is top or left.
        top_left = (by == ay and bx > ax) or by < ay
        inside &= (e > 0) | ((e == 0) & top_left)
    img[inside] = color
    return img


@pytest.mark.parametrize("seed", range(20))
def test_f_shading_against_my_naive_fill(seed):
    rng = np.random.default_rng(seed)
    vertices = np.round(rng.uniform(-5, 45, (3, 2)) * 4) / 4  # quarter pixels: on-edge centres
    vcolors = rng.uniform(0, 1, (3, 3))
    mine = naive_flat_fill(np.ones((40, 40, 3)), vertices, vcolors)
    theirs = scantrace.f_shading(np.ones((40, 40, 3)), vertices, vcolors)
    assert np.array_equal((mine != 1).any(axis=2), (theirs != 1).any(axis=2))
    np.testing.assert_allclose(mine, theirs, atol=1e-6)
