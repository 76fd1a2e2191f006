"""The benchmarks' helper in the module: the C++ render timed inside C++, on either clock."""

import numpy as np
import pytest

import scantrace
from conftest import random_scene, write_scene_json
from scantrace import _scantrace


@pytest.mark.parametrize("clock", ["wall", "cpu"])
@pytest.mark.parametrize("pixel", ["float32", "float64"])
def test_cpp_render_seconds_gives_one_positive_time_per_render(tmp_path, clock, pixel):
    v, f, c, d = random_scene(5, n_vertices=60, n_faces=80)
    path = str(write_scene_json(tmp_path / "scene.json", v, f, c, d))
    times = _scantrace._cpp_render_seconds(path, "g", 3, clock, pixel)
    assert len(times) == 3 and all(0 < t < 10 for t in times)


def test_cpp_float64_timing_leaves_render_img_exact(tmp_path):
    # The float64 timing renders into the image render_img recycles: the render after it must
    # still be the C++ float canvas's values, whatever the buffer held (a scene of another size
    # rendered into it first).
    v, f, c, d = random_scene(7, n_vertices=60, n_faces=80)
    small = str(write_scene_json(tmp_path / "small.json", v * 0.3, f, c, d, size=(97, 61)))
    _scantrace._cpp_render_seconds(small, "g", 2, "cpu", "float64")
    path = str(write_scene_json(tmp_path / "scene.json", v, f, c, d))
    img = scantrace.render_img(f, v, c, d, "g")
    assert (img == _scantrace._cpp_render_file(path, "g").astype(np.float64)).all()


def test_cpp_render_seconds_names_a_wrong_clock(tmp_path):
    v, f, c, d = random_scene(5, n_vertices=60, n_faces=80)
    path = str(write_scene_json(tmp_path / "scene.json", v, f, c, d))
    with pytest.raises(ValueError, match=r"^clock: expected 'wall' or 'cpu', got 'cycles'$"):
        _scantrace._cpp_render_seconds(path, "g", 1, "cycles")


def test_cpp_render_seconds_names_a_wrong_pixel(tmp_path):
    v, f, c, d = random_scene(5, n_vertices=60, n_faces=80)
    path = str(write_scene_json(tmp_path / "scene.json", v, f, c, d))
    with pytest.raises(ValueError, match=r"^pixel: expected 'float32' or 'float64', got 'u8'$"):
        _scantrace._cpp_render_seconds(path, "g", 1, "cpu", "u8")
