"""The course scene (../shared/data/hw1_2024.json, 10,000 faces): render_img equals the C++ float
canvas and the command's PNG. A file of its own so that CTest reports it SKIPPED, not passed, when
the scene is not there."""

import numpy as np

import scantrace
from scantrace import _scantrace
from conftest import run_cli


def test_course_scene(course_scene_path, tmp_path):
    scene = scantrace.load_scene(course_scene_path)
    f, v, c, d = scene["faces"], scene["vertices"], scene["vcolors"], scene["depth"]
    assert len(f) == 10000
    for shading in ("flat", "gouraud"):
        img = scantrace.render_img(f, v, c, d, shading[0])
        cpp = _scantrace._cpp_render_file(str(course_scene_path), shading[0])
        assert np.array_equal(img, cpp.astype(np.float64))
        run_cli("render", course_scene_path, "--shading", shading, "-o", tmp_path / "cli.png")
        scantrace.write_png(img, tmp_path / "py.png")
        assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()
