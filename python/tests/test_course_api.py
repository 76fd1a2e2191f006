"""The course's functions: signatures, conventions, and values derived by hand or independently."""

import inspect

import numpy as np
import pytest

import scantrace

TRIANGLE = np.array([[20.0, 20.0], [250.0, 80.0], [300.0, 400.0]])
RGB = np.eye(3)


def test_signatures_are_the_courses():
    names = lambda f: list(inspect.signature(f).parameters)  # noqa: E731
    assert names(scantrace.vector_interp) == ["p1", "p2", "V1", "V2", "coord", "dim"]
    assert names(scantrace.f_shading) == ["img", "vertices", "vcolors"]
    assert names(scantrace.g_shading) == ["img", "vertices", "vcolors"]
    assert names(scantrace.render_img) == ["faces", "vertices", "vcolors", "depth", "shading"]
    for f in (scantrace.vector_interp, scantrace.f_shading, scantrace.g_shading,
              scantrace.render_img, scantrace.render, scantrace.trace_triangle):
        assert f.__doc__ and len(f.__doc__) > 100


def test_vector_interp_hand_values():
    # Along x: a quarter of the way from x=0 to x=8.
    v = scantrace.vector_interp([0, 5], [8, 9], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0], 2, 1)
    np.testing.assert_allclose(v, [0.75, 0.0, 0.25])
    # Along y: p1 below p2, coordinate three quarters of the way.
    v = scantrace.vector_interp([3, 10], [7, 2], [0.0, 4.0, 8.0], [4.0, 0.0, 0.0], 4, 2)
    np.testing.assert_allclose(v, [3.0, 1.0, 2.0])
    # Scalars and longer vectors: the same per component.
    assert scantrace.vector_interp([0, 0], [10, 0], 0.0, 1.0, 2.5, 1) == pytest.approx(0.25)
    v = scantrace.vector_interp([0, 0], [0, 4], np.arange(5.0), np.arange(5.0) + 4, 1, 2)
    np.testing.assert_allclose(v, np.arange(5.0) + 1)
    # Outside the segment the line is extended.
    assert scantrace.vector_interp([0, 0], [10, 0], 0.0, 1.0, 20, 1) == pytest.approx(2.0)


def test_vector_interp_degenerate_is_the_midpoint():
    v = scantrace.vector_interp([5, 0], [5, 9], [0.0, 0.2, 1.0], [1.0, 0.4, 0.0], 5, 1)
    np.testing.assert_allclose(v, [0.5, 0.3, 0.5])
    v = scantrace.vector_interp([1, 1], [1, 1], 2.0, 4.0, 1, 2)
    assert v == pytest.approx(3.0)


def test_vector_interp_bad_dim():
    with pytest.raises(ValueError, match=r"dim: expected 1 \(along x\) or 2 \(along y\), got 3"):
        scantrace.vector_interp([0, 0], [1, 1], 0.0, 1.0, 0.5, 3)


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_f_shading_fills_in_place_and_returns_img(dtype):
    img = np.ones((64, 64, 3), dtype=dtype)
    out = scantrace.f_shading(img, [[0, 0], [10, 0], [0, 10]], RGB)
    assert out is img
    # Top-left rule: rows 0..9, row y holds x = 0 .. 9 - y (the hypotenuse x + y = 10 is a right
    # edge, so its centres are left out): 10 + 9 + ... + 1 = 55 pixels, all the mean colour.
    written = np.any(img != 1, axis=2)
    expected = np.zeros((64, 64), bool)
    for y in range(10):
        expected[y, : 10 - y] = True
    assert (written == expected).all()
    np.testing.assert_allclose(img[written], np.full((55, 3), 1 / 3), rtol=1e-6)


def test_g_shading_matches_barycentric_colours():
    img = np.ones((512, 512, 3))
    scantrace.g_shading(img, TRIANGLE, RGB)
    ys, xs = np.nonzero(np.any(img != 1, axis=2))
    # Barycentric coordinates of each written centre, computed here with numpy.
    (x0, y0), (x1, y1), (x2, y2) = TRIANGLE
    det = (y1 - y2) * (x0 - x2) + (x2 - x1) * (y0 - y2)
    l0 = ((y1 - y2) * (xs - x2) + (x2 - x1) * (ys - y2)) / det
    l1 = ((y2 - y0) * (xs - x2) + (x0 - x2) * (ys - y2)) / det
    l2 = 1 - l0 - l1
    assert (np.stack([l0, l1, l2]) >= -1e-12).all()  # only centres inside are written
    np.testing.assert_allclose(img[ys, xs], np.column_stack([l0, l1, l2]), atol=1e-4)
    # Twice the area is 230*380 - 280*60 = 70600; about that many pixels (a half-open fill of a
    # triangle covers its area give or take its perimeter).
    assert abs(len(xs) - 70600 / 2) < 1000


def test_shading_a_non_contiguous_view_writes_the_callers_array():
    base = np.ones((40, 80, 3))
    view = base[:, ::2]  # 40 x 40, not contiguous
    scantrace.g_shading(view, [[2, 2], [30, 5], [10, 35]], RGB)
    reference = scantrace.g_shading(np.ones((40, 40, 3)), [[2, 2], [30, 5], [10, 35]], RGB)
    assert (base[:, ::2] == reference).all()
    assert (base[:, 1::2] == 1).all()


def test_float64_image_holds_the_float_canvas_values():
    a = scantrace.g_shading(np.ones((100, 100, 3)), [[3, 4], [90, 20], [40, 95]], RGB)
    b = scantrace.g_shading(np.ones((100, 100, 3), np.float32), [[3, 4], [90, 20], [40, 95]], RGB)
    assert (a == b.astype(np.float64)).all()


def test_render_img_shape_background_and_painters_order():
    # Two overlapping triangles: the nearer (smaller depth) one is drawn last and wins.
    vertices = np.array([[10, 10], [100, 10], [10, 100], [20, 20], [120, 20], [20, 120]], float)
    faces = np.array([[3, 4, 5], [0, 1, 2]])
    vcolors = np.array([[1, 0, 0]] * 3 + [[0, 0, 1]] * 3, float)
    depth = np.array([1, 1, 1, 5, 5, 5], float)
    img = scantrace.render_img(faces, vertices, vcolors, depth, "f")
    assert img.shape == (512, 512, 3) and img.dtype == np.float64
    assert (img[0, 0] == 1).all() and (img[500, 500] == 1).all()
    assert tuple(img[30, 30]) == (1.0, 0.0, 0.0)   # both cover it; face 1 (red) is nearer
    assert tuple(img[60, 60]) == (0.0, 0.0, 1.0)  # only face 0 (blue)
    for s in ("g", "flat", "gouraud"):
        assert scantrace.render_img(faces, vertices, vcolors, depth, s).shape == (512, 512, 3)


def test_render_options():
    vertices = np.array([[0, 0], [30, 0], [0, 20]], float)
    faces = np.array([[0, 1, 2]])
    colors = np.full((3, 3), 0.5)
    img = scantrace.render(vertices, faces, colors, np.zeros(3), size=(40, 25),
                           background=(0, 0, 0), dtype=np.uint8)
    assert img.shape == (25, 40, 3) and img.dtype == np.uint8
    assert tuple(img[0, 0]) == (128, 128, 128) and tuple(img[24, 39]) == (0, 0, 0)
    # closed fills the centres on the right edge too: (30, 0) is a vertex on the hypotenuse.
    top_left = scantrace.render(vertices, faces, colors, np.zeros(3), size=(40, 25))
    closed = scantrace.render(vertices, faces, colors, np.zeros(3), size=(40, 25),
                              fill_rule="closed")
    assert (top_left[0, 30] == 1).all() and (closed[0, 30] == 0.5).all()
    assert (closed != 1).any(axis=2).sum() > (top_left != 1).any(axis=2).sum()
