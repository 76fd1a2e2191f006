"""Shared helpers of the Python tests: paths given by CTest, the course scene, random scenes."""

import html
import json
import os
import pathlib
import re
import subprocess

import numpy as np
import pytest

SHARED_DATA = pathlib.Path(os.environ.get("SCANTRACE_SHARED_DATA", "../shared/data"))
COURSE_SCENE = SHARED_DATA / "hw1_2024.json"
SCANTRACE = os.environ.get("SCANTRACE_BINARY", "scantrace")
SOURCE_DIR = pathlib.Path(os.environ.get("SCANTRACE_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture
def course_scene_path():
    if not COURSE_SCENE.exists():
        pytest.skip(f"the course scene {COURSE_SCENE} is not here")
    return COURSE_SCENE


def random_scene(seed, n_vertices=60, n_faces=80, size=(512, 512)):
    """A scene of random triangles, some off the canvas, sharing vertices."""
    rng = np.random.default_rng(seed)
    w, h = size
    vertices = np.column_stack([rng.uniform(-40, w + 40, n_vertices),
                                rng.uniform(-40, h + 40, n_vertices)])
    # Some vertices on whole and half pixels, where the fill rule decides.
    vertices[::4] = np.round(vertices[::4] * 2) / 2
    faces = rng.integers(0, n_vertices, (n_faces, 3))
    vcolors = rng.uniform(0, 1, (n_vertices, 3))
    depth = rng.uniform(0, 100, n_vertices)
    return vertices, faces, vcolors, depth


def write_scene_json(path, vertices, faces, vcolors, depth, size=(512, 512), background=None):
    """The scene file the command line reads (repr of a float reads back bit for bit)."""
    scene = {"vertices": vertices.tolist(), "faces": faces.tolist(),
             "vcolors": vcolors.tolist(), "depth": depth.tolist(),
             "width": size[0], "height": size[1]}
    if background is not None:
        scene["background"] = list(background)
    path.write_text(json.dumps(scene))
    return path


def run_cli(*args):
    return subprocess.run([SCANTRACE, *map(str, args)], capture_output=True, text=True,
                          check=True)


def run_in_chromium(page_path, tmp_path):
    """Opens page_path in headless Chromium, lets its scripts run (virtual time: timers and
    image loads finish) and returns the JSON its script left in <pre id="result">."""
    r = subprocess.run(
        ["chromium", "--headless", "--no-sandbox", "--disable-gpu", "--virtual-time-budget=30000",
         "--host-resolver-rules=MAP * ~NOTFOUND", f"--user-data-dir={tmp_path / 'profile'}",
         "--dump-dom", page_path.as_uri()],
        capture_output=True, text=True, timeout=120)
    m = re.search(r'<pre id="result">(.*?)</pre>', r.stdout, re.S)
    assert m, f"the page did not finish: {r.stderr[-2000:]}"
    return json.loads(html.unescape(m.group(1)))
