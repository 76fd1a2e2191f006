"""The scene arrays' checks see every element: the finiteness, index and colour-range checks run
as vectorized passes without an exit (python/src/arrays.cpp), and a pass that missed the tail of
an array (a length not a multiple of the vector width) or its first element would let a bad
value through. Each case puts one bad value at one position of arrays of several lengths and
expects the error naming that element, as the per-element checks name it."""

import numpy as np
import pytest

import scantrace

LENGTHS = (3, 4, 5, 7, 17, 1001)


def scene(n):
    """n vertices on a circle and the fan of triangles over them (n - 2 faces)."""
    a = np.linspace(0, 2 * np.pi, n, endpoint=False)
    vertices = np.stack([256 + 200 * np.cos(a), 256 + 200 * np.sin(a)], axis=1)
    faces = np.array([[0, i, i + 1] for i in range(1, n - 1)], dtype=np.int64)
    return dict(vertices=vertices, faces=faces, vcolors=np.full((n, 3), 0.25),
                depth=np.linspace(1, 2, n))


def positions(n):
    return sorted({0, 1, n // 2, n - 2, n - 1})


def render(s):
    return scantrace.render(s["vertices"], s["faces"], s["vcolors"], s["depth"], shading="g")


@pytest.mark.parametrize("n", LENGTHS)
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_a_non_finite_vertex_or_depth_is_named_wherever_it_is(n, bad):
    for i in positions(n):
        for j in (0, 1):
            s = scene(n)
            s["vertices"][i, j] = bad
            with pytest.raises(ValueError, match=rf"^vertices\[{i}\]: NaN and infinity"):
                render(s)
        s = scene(n)
        s["depth"][i] = bad
        with pytest.raises(ValueError, match=rf"^depth\[{i}\]: NaN and infinity"):
            render(s)


@pytest.mark.parametrize("n", LENGTHS)
@pytest.mark.parametrize("bad", [-0.001, 1.001, 7.0])
def test_a_colour_outside_the_unit_range_is_named_wherever_it_is(n, bad):
    for i in positions(n):
        for k in range(3):
            s = scene(n)
            s["vcolors"][i, k] = bad
            with pytest.raises(ValueError,
                               match=rf"^vcolors\[{i}\]: colour .* outside \[0, 1\]$"):
                render(s)


@pytest.mark.parametrize("n", LENGTHS)
@pytest.mark.parametrize("bad", [-1, -(2 ** 40), "n", 2 ** 40])
def test_a_vertex_index_out_of_range_is_named_wherever_it_is(n, bad):
    k = n - 2
    for f in sorted({0, k // 2, k - 1}):
        for j in range(3):
            s = scene(n)
            value = n if bad == "n" else bad
            s["faces"][f, j] = value
            with pytest.raises(ValueError, match=rf"^faces\[{f}\]: vertex index {value} is "
                                                 rf"out of range \({n} vertices\)$"):
                render(s)


def test_the_first_bad_element_is_the_one_named():
    s = scene(50)
    s["vcolors"][[7, 30]] = 2.0
    s["faces"][[5, 40], 1] = 99
    with pytest.raises(ValueError, match=r"^faces\[5\]: vertex index 99"):
        render(s)
    s["faces"] = scene(50)["faces"]
    with pytest.raises(ValueError, match=r"^vcolors\[7\]: "):
        render(s)


def test_the_edges_of_the_ranges_are_accepted():
    s = scene(17)
    s["vcolors"][0] = [0.0, 1.0, 0.0]
    s["vcolors"][-1] = [1.0, 0.0, 1.0]
    s["vertices"][3] = [-1e300, 1e300]  # huge but finite: the fill skips what it cannot reach
    s["faces"][-1] = [16, 16, 0]
    assert render(s).shape == (512, 512, 3)
