"""The parts of the grader's speed that can be held: what is the same for both shadings is
computed once per scene, a triangle's exact fill once per process (callers still get a mask of
their own), and class mode reports the grader's own CPU per submission without the student's."""

import re

import numpy as np

from scantrace.grade import battery, classmode, fill_models, hidden
from scantrace.grade import __main__ as cli

from conftest import CORRECT, write_submission


def test_the_painter_face_ids_are_found_once_per_scene(monkeypatch):
    calls = []
    real = battery._painter_faces
    monkeypatch.setattr(battery, "_painter_faces", lambda s: calls.append(1) or real(s))
    b = battery.Battery.__new__(battery.Battery)
    b._references = {}
    scene = hidden.scenes(3, 1)[0]
    flat = b._scene_references("hidden1", scene, "f", painter=True)
    gouraud = b._scene_references("hidden1", scene, "g", painter=True)
    assert len(calls) == 1                       # the same for both shadings
    assert flat["faces"] is gouraud["faces"]
    assert not (flat["reference"] == gouraud["reference"]).all()   # the shadings differ
    b._drop_scene("hidden1")
    assert ("hidden1", "faces") not in b._references
    assert ("hidden1", "uncovered") not in b._references


def test_a_triangles_exact_fill_is_computed_once_and_each_caller_owns_its_mask(monkeypatch):
    fill_models._correct_once.cache_clear()
    calls = []
    real = fill_models._spans
    monkeypatch.setattr(fill_models, "_spans", lambda *a, **k: calls.append(1) or real(*a, **k))
    tri = np.array([[0, 0], [4, 0], [0, 4]], np.int64)
    # By hand, the half-open rule: rows 0..3, row y filling columns 0 .. ceil(4 - y) - 1.
    expected = np.zeros((5, 5), bool)
    for y in range(4):
        expected[y, :4 - y] = True
    first = fill_models.correct(tri, (5, 5))
    first[:] = False                              # a caller changing its mask
    again = fill_models.correct(tri.astype(float), (5, 5))
    assert len(calls) == 1
    assert (again == expected).all()


def test_the_own_time_line_is_the_median_and_the_largest():
    rows = [{"grader_cpu": 0.2}, {"grader_cpu": 0.5}, {"grader_cpu": 0.3}, {"name": "died"}]
    assert classmode.own_time_line(rows).endswith("median 0.30 s, largest 0.50 s, over 3")


def test_class_mode_reports_the_graders_cpu_without_the_students(tmp_path, sandbox_ok, capsys):
    """A student whose import burns 1.5 s of CPU in the sandbox: the grader's own CPU per
    submission stays well below it (the grader's part is a few tenths of a second)."""
    burn = ("    import time\n    t0 = time.process_time()\n"
            "    while time.process_time() - t0 < 1.5:\n        pass\n")
    source = CORRECT.replace("def f_shading(img, vertices, vcolors):\n",
                             "def f_shading(img, vertices, vcolors):\n" + burn, 1)
    assert source != CORRECT
    # Only the first probe's call burns (all of them would take minutes).
    source = source.replace("    while time", "    if getattr(f_shading, 'burnt', False):\n"
                            "        t0 -= 2\n    f_shading.burnt = True\n    while time", 1)
    paths = [write_submission(tmp_path / f"s{k}", source) for k in range(2)]
    status = cli.main([*map(str, paths), "-o", str(tmp_path / "out"), "--jobs", "2",
                       "--call-seconds", "60"])
    assert status == 0
    line = [x for x in capsys.readouterr().err.splitlines() if "own CPU" in x][-1]
    median, largest, count = re.search(r"median ([\d.]+) s, largest ([\d.]+) s, over (\d+)",
                                       line).groups()
    assert int(count) == 2
    assert 0 < float(median) <= float(largest) < 1.5
