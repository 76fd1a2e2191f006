"""`diff` tells the truth in plain words (issue 47): no global mistake made up from one bright
pixel, notes only where they hold. The scene is the course's (the demo scene when
../shared/data is absent); the command line and Python give the same answer."""

import subprocess

import numpy as np
import pytest

import scantrace
from conftest import COURSE_SCENE, SCANTRACE, write_scene_json


@pytest.fixture(scope="module")
def scene_and_file(tmp_path_factory):
    """(scene dict, the scene file the command reads)."""
    if COURSE_SCENE.exists():
        return scantrace.load_scene(COURSE_SCENE), COURSE_SCENE
    s = scantrace.demo_scene()
    path = tmp_path_factory.mktemp("scene") / "demo.json"
    write_scene_json(path, s["vertices"], s["faces"], s["vcolors"], s["depth"],
                     size=tuple(s["size"]), background=s["background"])
    return s, path


def _cli_diff(scene_path, image_path):
    r = subprocess.run([SCANTRACE, "-q", "diff", str(scene_path), str(image_path), "--json"],
                       capture_output=True, text=True)
    assert r.returncode in (0, 3), r.stderr
    import json
    return json.loads(r.stdout)


def test_one_bright_pixel_is_one_differing_pixel(scene_and_file, tmp_path):
    scene, path = scene_and_file
    img = scantrace.render(**scene)
    img[300, 250] = [1.01, .5, .5]
    # Independently: the pixel differed from the reference before (its colour was not this).
    assert np.abs(scantrace.render(**scene)[300, 250] - [1.01, .5, .5]).max() > 1 / 255
    report = scantrace.diff(scene, img)
    assert report.differing_pixels == 1
    assert report.global_mistakes == []
    assert any("1 pixel above 1.0 (largest 1.01)" in n for n in report.notes), report.notes
    np.save(tmp_path / "img.npy", img)
    cli = _cli_diff(path, tmp_path / "img.npy")
    assert cli["differing_pixels"] == 1
    assert cli["global"] == []


def test_extrapolated_colours_are_a_note(scene_and_file):
    scene, _ = scene_and_file
    good = scantrace.render(**scene)
    img = good.copy()
    ys, xs = np.nonzero((good < 0.9).all(axis=2))
    pick = np.linspace(0, len(ys) - 1, 12).astype(int)
    img[ys[pick], xs[pick], 0] = np.linspace(1.06, 1.28, 12)
    report = scantrace.diff(scene, img)
    assert report.global_mistakes == []
    assert report.differing_pixels == 12
    assert any("12 pixels above 1.0 (largest 1.28)" in n for n in report.notes), report.notes


def test_a_float_render_gets_no_8bit_note(scene_and_file):
    """A float64 image a little darker than the reference (within the tolerance) never went
    through 8 bits: no truncation note, although a few of its values are k/255 by chance."""
    scene, _ = scene_and_file
    img = scantrace.render(**scene) - 0.7 / 255
    report = scantrace.diff(scene, img)
    assert report.differing_pixels == 0
    assert not any("truncation" in n for n in report.notes), report.notes
    # An image that did go through 8 bits, truncated, keeps the note (issue 36).
    truncated = np.floor(scantrace.render(**scene) * 255 + 1e-9) / 255
    assert any("truncation" in n for n in scantrace.diff(scene, truncated).notes)


def _too_wide_render(scene):
    """A flat render as a student's floor/ceil fill draws it: columns floor(x_L) .. ceil(x_R),
    both included (the pixels a line drawing of the edges lights), painter's order, written here
    independently of the package."""
    v, f, c, d = (np.asarray(scene[k], float) for k in ("vertices", "faces", "vcolors", "depth"))
    f = f.astype(int)
    w, h = (int(n) for n in scene["size"])
    img = np.ones((h, w, 3))
    for face in np.argsort(-d[f].mean(axis=1), kind="stable"):
        tri, colour = v[f[face]], c[f[face]].mean(axis=0)
        for y in range(max(0, int(np.ceil(tri[:, 1].min()))),
                       min(h, int(np.ceil(tri[:, 1].max())))):
            xs = [a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
                  for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0]))
                  if min(a[1], b[1]) <= y < max(a[1], b[1])]
            if len(xs) == 2:
                x0, x1 = int(np.floor(min(xs))), int(np.ceil(max(xs)))
                img[y, max(0, x0):min(w, x1 + 1)] = colour
    return img


def test_verdict_names_spans_too_wide_first(scene_and_file):
    scene, _ = scene_and_file
    report = scantrace.diff(scene, _too_wide_render(scene), shading="flat")
    assert report.verdict, str(report)
    first = report.verdict[0]
    assert first["id"] == "span_too_wide", report.verdict
    assert first["text"] == "spans are one pixel too wide on both sides (floor(x_L) .. ceil(x_R)?)"
    text = str(report)
    assert text.index(first["text"]) < text.index("pixels differ")
    page = report._repr_html_()
    assert page.index("spans are one pixel too wide") < page.index("<table>")
    assert repr(report).startswith("<DiffReport: spans are one pixel too wide")


def test_verdict_names_a_reversed_painters_order(scene_and_file):
    scene, _ = scene_and_file
    reversed_order = scantrace.render(scene["vertices"], scene["faces"], scene["vcolors"],
                                      -np.asarray(scene["depth"], float), size=scene["size"],
                                      background=scene["background"])
    report = scantrace.diff(scene, reversed_order)
    assert {"id": "order_reversed", "text": "faces are painted nearest first"}.items() <= \
        report.verdict[0].items(), report.verdict
