"""The benchmarks' helper in the module: the C++ render timed inside C++, on either clock."""

import pytest

from conftest import random_scene, write_scene_json
from scantrace import _scantrace


@pytest.mark.parametrize("clock", ["wall", "cpu"])
def test_cpp_render_seconds_gives_one_positive_time_per_render(tmp_path, clock):
    v, f, c, d = random_scene(5, n_vertices=60, n_faces=80)
    path = str(write_scene_json(tmp_path / "scene.json", v, f, c, d))
    times = _scantrace._cpp_render_seconds(path, "g", 3, clock)
    assert len(times) == 3 and all(0 < t < 10 for t in times)


def test_cpp_render_seconds_names_a_wrong_clock(tmp_path):
    v, f, c, d = random_scene(5, n_vertices=60, n_faces=80)
    path = str(write_scene_json(tmp_path / "scene.json", v, f, c, d))
    with pytest.raises(ValueError, match=r"^clock: expected 'wall' or 'cpu', got 'cycles'$"):
        _scantrace._cpp_render_seconds(path, "g", 1, "cycles")
