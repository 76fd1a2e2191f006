"""Python renders equal the C++ render: the float canvas value for value, and the command's PNG
byte for byte after the same 8-bit conversion."""

import numpy as np
import pytest

import scantrace
from scantrace import _scantrace
from conftest import random_scene, run_cli, write_scene_json


@pytest.mark.parametrize("seed", [1, 2, 3, 4, 5])
@pytest.mark.parametrize("shading", ["f", "g"])
def test_random_scene_equals_the_cpp_float_canvas(tmp_path, seed, shading):
    v, f, c, d = random_scene(seed)
    path = write_scene_json(tmp_path / "scene.json", v, f, c, d)
    cpp = _scantrace._cpp_render_file(str(path), shading)  # Image<Rgb32f>, from the file
    assert cpp.dtype == np.float32
    img = scantrace.render_img(f, v, c, d, shading)
    assert img.dtype == np.float64 and img.shape == cpp.shape
    assert np.array_equal(img, cpp.astype(np.float64))
    assert np.array_equal(scantrace.render(v, f, c, d, shading=shading, dtype=np.float32), cpp)
    assert (img != 1).any()  # the scene did draw something


@pytest.mark.parametrize("shading", ["flat", "gouraud"])
def test_png_bytes_equal_the_commands(tmp_path, shading):
    v, f, c, d = random_scene(11, n_vertices=200, n_faces=300)
    path = write_scene_json(tmp_path / "scene.json", v, f, c, d)
    run_cli("render", path, "--shading", shading, "-o", tmp_path / "cli.png")
    img = scantrace.render_img(f, v, c, d, shading[0])
    scantrace.write_png(img, tmp_path / "py.png")
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()
    # uint8 output: round(255 c), the PNG's pixels (a deliberately different rounding differs).
    u8 = scantrace.render(v, f, c, d, shading=shading, dtype=np.uint8)
    expected = np.clip(np.floor(255 * img.astype(np.float32).astype(np.float64) + 0.5), 0, 255)
    assert np.array_equal(u8, expected.astype(np.uint8))
    assert not np.array_equal(u8, (255 * img).astype(np.uint8))


def test_size_and_background_equal_the_cpp_render(tmp_path):
    v, f, c, d = random_scene(21, size=(300, 170))
    path = write_scene_json(tmp_path / "scene.json", v, f, c, d, size=(300, 170),
                            background=(0.25, 0.5, 0.75))
    cpp = _scantrace._cpp_render_file(str(path), "g")
    img = scantrace.render(v, f, c, d, size=(300, 170), background=(0.25, 0.5, 0.75))
    assert img.shape == (170, 300, 3)
    assert np.array_equal(img, cpp.astype(np.float64))


def test_load_scene_round_trip(tmp_path):
    v, f, c, d = random_scene(31)
    path = write_scene_json(tmp_path / "scene.json", v, f, c, d, size=(200, 100))
    scene = scantrace.load_scene(path)
    assert set(scene) == {"vertices", "faces", "vcolors", "depth", "size", "background"}
    assert np.array_equal(scene["vertices"], v) and np.array_equal(scene["faces"], f)
    assert np.array_equal(scene["vcolors"], c) and np.array_equal(scene["depth"], d)
    assert scene["size"] == (200, 100) and scene["background"] == (1.0, 1.0, 1.0)
    assert np.array_equal(scantrace.render(**scene),
                          _scantrace._cpp_render_file(str(path), "g").astype(np.float64))


def test_obj_model_renders_like_the_command(tmp_path):
    from conftest import SOURCE_DIR
    model = SOURCE_DIR / "examples" / "models" / "interpenetrating.obj"
    scene = scantrace.load_scene(model)
    assert len(scene["faces"]) > 0
    run_cli("render", model, "--depth", "painter", "--cull", "none", "-o", tmp_path / "cli.png")
    scantrace.write_png(scantrace.render(**scene), tmp_path / "py.png")
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()


@pytest.mark.parametrize("dtype", [np.float64, np.float32, np.uint8])
def test_a_scene_of_high_overdraw_renders_as_its_nearest_face_alone(tmp_path, dtype):
    """3,000 copies of one large triangle at one depth, each its own colour: the library renders
    such a scene near to far (its overdraw estimate), and the painter's result is the last face's
    fill alone (ties keep face order, so the last face is drawn last), computed here by g_shading
    on a white image. The render's array is the library's image itself, handed to numpy."""
    n = 3000
    triangle = np.array([[30.5, 12.25], [490.0, 200.75], [140.125, 505.5]])
    vertices = np.tile(triangle, (n, 1))
    faces = np.arange(3 * n).reshape(n, 3)
    rng = np.random.default_rng(7)
    vcolors = rng.uniform(0, 1, (3 * n, 3))
    depth = np.full(3 * n, 5.0)
    img = scantrace.render(vertices, faces, vcolors, depth, dtype=dtype)
    last = scantrace.g_shading(np.ones((512, 512, 3)), triangle, vcolors[-3:])
    expected = {np.float64: last, np.float32: last.astype(np.float32),
                np.uint8: np.round(last * 255).astype(np.uint8)}[dtype]
    assert img.dtype == dtype and img.shape == (512, 512, 3) and img.flags["C_CONTIGUOUS"]
    assert np.array_equal(img, expected)
    del img  # the array owns the image: nothing is left behind


@pytest.mark.parametrize("seed", [41, 42])
def test_partly_hidden_gouraud_spans_equal_the_cpp_float_canvas(tmp_path, seed):
    """Hundreds of large overlapping triangles: rendered near to far (high overdraw), most
    Gouraud spans are partly covered by nearer faces and written in their visible runs, each pixel
    with the colour of the whole span at that pixel (the float64 canvas's own span writer,
    array_canvas.hpp). Value for value the C++ float canvas, read from the same file."""
    v, f, c, d = random_scene(seed, n_vertices=300, n_faces=600)
    path = write_scene_json(tmp_path / "scene.json", v, f, c, d)
    cpp = _scantrace._cpp_render_file(str(path), "g").astype(np.float64)
    img = scantrace.render_img(f, v, c, d, "g")
    assert np.array_equal(img, cpp)
    assert len(np.unique(img.reshape(-1, 3), axis=0)) > 10000  # shaded, not flat


def test_a_later_render_never_writes_a_live_array():
    """A dropped render's storage is reused by the next render (course.cpp's RecycledImage): an
    array still alive, or a view of one whose array was dropped, keeps its pixels."""
    v, f, c, d = random_scene(51)
    first = scantrace.render_img(f, v, c, d, "g")
    kept = first.copy()
    view = scantrace.render_img(f, v, c, d, "f")[100:200]
    kept_view = view.copy()
    for shading in ("f", "g", "f"):
        other = scantrace.render(v[::-1].copy(), f, c, d, shading=shading)
        assert not np.shares_memory(other, first) and not np.shares_memory(other, view)
        del other
    assert np.array_equal(first, kept) and np.array_equal(view, kept_view)

