"""Property tests (Debian's python3-hypothesis) over triangles and images: whatever numbers a caller
passes, a call either answers or raises one TypeError/ValueError line naming the argument; and
what it answers holds what an independent computation says."""

import numpy as np
import pytest

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import given, settings, strategies as st  # noqa: E402
from hypothesis.extra import numpy as hnp  # noqa: E402

import scantrace  # noqa: E402

coordinate = st.one_of(st.floats(-1e6, 1e6), st.floats(allow_nan=True, allow_infinity=True),
                       st.sampled_from([0.0, 0.5, 511.5, 1e300, -1e300]))
triangle = st.lists(st.tuples(coordinate, coordinate), min_size=3, max_size=3)
FAST = settings(max_examples=60, deadline=None)


def refused(e, names):
    message = str(e)
    assert message and "\n" not in message
    assert message.split(":")[0].split("[")[0] in names, message


@FAST
@given(triangle)
def test_a_triangle_is_filled_or_refused_in_one_line(vertices):
    img = np.ones((64, 64, 3))
    try:
        scantrace.f_shading(img, vertices, np.eye(3))
    except ValueError as e:
        refused(e, {"vertices"})
        assert not np.isfinite(np.array(vertices, float)).all()
        return
    assert np.isfinite(np.array(vertices, float)).all()
    # Written pixels hold the flat colour (the mean of the identity's rows) and nothing else.
    written = (img != 1).any(axis=2)
    assert np.allclose(img[written], np.float32(1 / 3))


@FAST
@given(triangle)
def test_the_trace_of_a_triangle_checks(vertices):
    try:
        t = scantrace.trace_triangle(vertices, np.eye(3), size=(48, 40))
    except ValueError as e:
        refused(e, {"vertices"})
        return
    assert scantrace.check(t).ok
    # The trace's image is the image the fill draws.
    img = np.ones((40, 48, 3))
    scantrace.g_shading(img, vertices, np.eye(3))
    np.testing.assert_array_equal(t.image, img)


image_dtypes = st.sampled_from([np.uint8, np.float32, np.float64, np.int16, np.bool_, ">f8"])


@FAST
@given(hnp.arrays(image_dtypes, hnp.array_shapes(min_dims=1, max_dims=4, min_side=0, max_side=6)))
def test_any_array_given_to_diff_is_compared_or_refused(image):
    scene = ([[0, 1, 2]], np.array([[0, 0], [5, 0], [0, 5]], float), np.eye(3), np.zeros(3))
    try:
        report = scantrace.diff(scene, image)
    except (TypeError, ValueError) as e:
        refused(e, {"image"})
        return
    assert image.ndim == 3 and image.shape[2] == 3 and image.shape[0] and image.shape[1]
    assert report.compared_pixels > 0


# The scene's checks run on the bits of the values (python/src/arrays.cpp: all_finite,
# all_in_unit_range, the faces' range): the boundary values of those tricks against numpy's plain
# comparisons. -0.0 is a colour in range (it equals 0); the smallest double above 1 and the
# largest finite double are not, nor are the smallest negative subnormal and a value below -1
# (whose bits, read unsigned, lie above those of 1.0 minus 2^63).
edge_values = [0.0, -0.0, 1.0, np.nextafter(1.0, 2.0), np.nextafter(0.0, -1.0),
               np.nextafter(0.0, 1.0), 0.5, 2.0, -1.0, -2.0, 1.7976931348623157e308,
               -1.7976931348623157e308, -1e-300,
               np.nan, np.inf, -np.inf]
bad_index = st.sampled_from([-2 ** 63, -1, 5, 2 ** 62])
poke = st.one_of(st.tuples(st.just("vertices"), st.integers(0, 9), st.sampled_from(edge_values)),
                 st.tuples(st.just("vcolors"), st.integers(0, 14), st.sampled_from(edge_values)),
                 st.tuples(st.just("faces"), st.integers(0, 8), bad_index))


@settings(max_examples=300, deadline=None)
@given(st.lists(poke, max_size=3))
def test_a_scene_is_refused_exactly_when_a_plain_check_refuses_it(pokes):
    # A valid scene of 5 vertices and 3 faces, then up to three values replaced.
    arrays = {"vertices": np.linspace(0, 15, 10).reshape(5, 2),
              "vcolors": np.linspace(0, 1, 15).reshape(5, 3),
              "faces": np.array([[0, 1, 2], [2, 3, 4], [4, 0, 1]], np.int64)}
    for name, index, value in pokes:
        arrays[name].reshape(-1)[index] = value
    v, c, f = arrays["vertices"], arrays["vcolors"], arrays["faces"]
    problems = {"vertices": not np.isfinite(v).all(),
                "vcolors": not (np.isfinite(c).all() and (c >= 0).all() and (c <= 1).all()),
                "faces": not ((f >= 0) & (f < 5)).all()}
    try:
        scantrace.render(v, f, c, np.arange(5.0), size=(16, 16))
    except ValueError as e:
        refused(e, {name for name, bad in problems.items() if bad})
        return
    assert not any(problems.values())
