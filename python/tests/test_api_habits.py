"""The API forgives a student's habits (issue 47): numpy integers where an int is taken, shading
names in any case, integer 0-255 images of any dtype in diff, a (faces, vertices) swap named in
the error, scanline() outside a triangle's rows explained, single-face traces keeping the face's
id. Each compares with the plain call's answer or with values computed here."""

import math

import numpy as np
import pytest

import scantrace


@pytest.fixture(scope="module")
def scene():
    return scantrace.demo_scene()


def test_numpy_integers_are_ints(scene):
    ys, xs = np.nonzero(scantrace.render(**scene).sum(axis=2) < 2.5)
    x, y = xs[len(xs) // 2], ys[len(ys) // 2]
    assert isinstance(x, np.integer)
    assert scantrace.why(scene, x, y).to_json() == scantrace.why(scene, int(x), int(y)).to_json()
    assert scantrace.why(scene, np.int32(256), np.uint16(100)).pixel == (256, 100)
    t = scantrace.trace_scene(**scene, max_events=np.int64(50))
    assert len(t) <= 52  # the header and the footer besides
    with pytest.raises(TypeError, match="x: expected an int"):
        scantrace.why(scene, np.bool_(True), 3)
    with pytest.raises(TypeError, match="x: expected an int"):
        scantrace.why(scene, np.float64(3.0), 3)


@pytest.mark.parametrize("given, plain", [("F", "f"), ("Flat", "flat"), ("GOURAUD", "gouraud"),
                                          ("G", "g")])
def test_shading_in_any_case(scene, given, plain):
    args = (scene["faces"], scene["vertices"], scene["vcolors"], scene["depth"])
    assert np.array_equal(scantrace.render_img(*args, given), scantrace.render_img(*args, plain))
    assert scantrace.diff(scene, scantrace.render(**scene, shading=plain),
                          shading=given).agrees


@pytest.mark.parametrize("dtype", [np.int64, np.int32, np.int16, np.uint16, np.uint32])
def test_integer_images_of_any_dtype(scene, dtype):
    img = scantrace.render(**scene)
    img[10:20, 10:20] = 0.2  # a wrong patch, so that there is something to report
    bytes8 = np.round(img * 255).astype(np.uint8)
    expected = scantrace.diff(scene, bytes8)
    got = scantrace.diff(scene, bytes8.astype(dtype))
    assert got.differing_pixels == expected.differing_pixels > 0
    assert got.categories == expected.categories


def test_integer_image_outside_0_255_is_named(scene):
    img = np.round(scantrace.render(**scene) * 255).astype(np.int64)
    img[3, 7, 1] = 300
    with pytest.raises(ValueError, match=r"image\[3, 7\]: an integer image holds 8-bit values "
                                         r"0 \.\. 255, got 300"):
        scantrace.diff(scene, img)


def test_swapped_faces_and_vertices_are_named(scene):
    v, f, c, d = scene["vertices"], scene["faces"], scene["vcolors"], scene["depth"]
    swapped = "faces and vertices look swapped"
    with pytest.raises(ValueError, match=swapped) as e:
        scantrace.render(f, v, c, d)
    assert "render_img, and a scene given to why or diff as a tuple, the course's (faces, " \
           "vertices, …)" in str(e.value)
    with pytest.raises(ValueError, match=swapped):
        scantrace.render_img(v, f, c, d, "f")
    with pytest.raises(ValueError, match=swapped):
        scantrace.diff((v, f, c, d), scantrace.render(**scene))


def test_scanline_outside_the_rows_says_why():
    vertices = [[20, 20], [250, 80], [300, 400]]
    t = scantrace.trace_triangle(vertices, np.eye(3))
    first = math.ceil(min(v[1] for v in vertices))
    last = math.ceil(max(v[1] for v in vertices)) - 1
    assert t.has_scanline(0, last) and not t.has_scanline(0, last + 1)
    with pytest.raises(IndexError) as e:
        t.scanline(0, last + 1)
    assert str(e.value) == (f"row {last + 1} is not filled: triangle 0's rows are {first}..{last} "
                            "(ceil(y_min) .. ceil(y_max) − 1: the top-left rule leaves the "
                            "bottom vertex's row out)")
    with pytest.raises(IndexError, match=r"row 5 is not filled: .* above the triangle's top"):
        t.scanline(0, 5)
    with pytest.raises(IndexError, match="triangle 7 is not in the trace; it holds triangle"):
        t.scanline(7, 100)


def test_a_single_face_trace_keeps_its_id(scene):
    f = 123
    v = scene["vertices"][scene["faces"][f]]
    c = scene["vcolors"][scene["faces"][f]]
    t = scantrace.trace_triangle(v, c, face=np.int64(f))
    t0 = scantrace.trace_triangle(v, c)
    assert t.triangles() == [f]
    assert "triangle" in repr(t) and f"[{f}]" in repr(t)
    rows = [s.y for s in t0.scanlines(0)]
    assert rows and [s.y for s in t.scanlines(f)] == rows
    spans = [(t.scanline(f, y).span.x_begin, t.scanline(f, y).span.x_end) for y in rows]
    assert spans == [(t0.scanline(0, y).span.x_begin, t0.scanline(0, y).span.x_end) for y in rows]
    assert scantrace.check(t).ok
    assert np.array_equal(t.image, t0.image)


def test_integer_npy_files_of_any_dtype(scene, tmp_path):
    """np.save of an int64 0..255 image: diff reads it, from Python and from the command."""
    import json
    import subprocess

    from conftest import SCANTRACE, write_scene_json
    img = np.round(scantrace.render(**scene) * 255).astype(np.int64)
    img[5:9, 5:9] = 0  # 16 pixels wrong
    np.save(tmp_path / "img.npy", img)
    expected = scantrace.diff(scene, img.astype(np.uint8))
    assert scantrace.diff(scene, tmp_path / "img.npy").differing_pixels == \
        expected.differing_pixels > 0
    path = write_scene_json(tmp_path / "scene.json", scene["vertices"], scene["faces"],
                            scene["vcolors"], scene["depth"], size=tuple(scene["size"]),
                            background=scene["background"])
    r = subprocess.run([SCANTRACE, "-q", "diff", str(path), str(tmp_path / "img.npy"), "--json"],
                       capture_output=True, text=True)
    assert r.returncode == 3, r.stderr
    assert json.loads(r.stdout)["differing_pixels"] == expected.differing_pixels
