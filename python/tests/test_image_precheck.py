"""diff of an image file from Python goes through the command's one pre-check (C++,
grade/image_precheck.hpp; issue 46 #16): a header declaring another size than the scene's canvas
is the command's canvas_size report, made from the header alone, for PNG and .npy files alike."""

import json
import struct
import subprocess
import time

import numpy as np
import pytest

import scantrace
from conftest import SCANTRACE, random_scene, write_scene_json


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    d = tmp_path_factory.mktemp("precheck")
    v, f, c, z = random_scene(3, n_vertices=30, n_faces=30, size=(64, 48))
    return write_scene_json(d / "scene.json", v, f, c, z, size=(64, 48))


def tiny_png(width, height):
    """A PNG of a few dozen bytes declaring width x height: IHDR, a one-byte IDAT (decoded, an
    error) and IEND."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + b"\0\0\0\0"
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", b"x") + chunk(b"IEND", b"")


def command_report(scene, image):
    r = subprocess.run([SCANTRACE, "-q", "diff", str(scene), str(image), "--json"],
                       capture_output=True, text=True)
    assert r.returncode == 3, r.stderr
    return json.loads(r.stdout)


def test_a_png_declaring_16000_squared_is_the_commands_canvas_size_report(scene, tmp_path):
    pytest.importorskip("scantrace._scantrace_cv")
    big = tmp_path / "big.png"
    big.write_bytes(tiny_png(16000, 16000))
    t0 = time.monotonic()
    report = scantrace.diff(scene, big)
    assert time.monotonic() - t0 < 2
    assert json.loads(report.to_json()) == command_report(scene, big)
    assert [g["kind"] for g in report.global_mistakes] == ["canvas_size"]
    assert report.image_size == {"width": 16000, "height": 16000}
    assert report.compared_pixels == 0
    assert report.diff_image().shape == (48, 64, 3)


def test_a_npy_of_another_shape_is_answered_without_reading_its_values(scene, tmp_path):
    # NaN everywhere: read, its values are an error; its shape alone answers.
    path = tmp_path / "nan.npy"
    np.save(path, np.full((10, 12, 3), np.nan, dtype=np.float32))
    report = scantrace.diff(scene, path)
    assert json.loads(report.to_json()) == command_report(scene, path)
    assert report.global_mistakes[0]["text"] == "the image is 12x10, the scene's canvas is 64x48"
    # At the canvas's size the values are read, and NaN is the command's error.
    np.save(path, np.full((48, 64, 3), np.nan, dtype=np.float32))
    with pytest.raises(scantrace.InputError, match="NaN"):
        scantrace.diff(scene, path)


def test_the_budget_is_the_commands_for_a_npy(scene, tmp_path, monkeypatch):
    # A 4000 x 3000 uint8 .npy (36 MB, read whole) against a canvas of that size under a 64 MiB
    # budget: its float pixels (137 MiB) are refused in the command's words
    # (grade/image_header.cpp), not by the .npy reader's own estimate ("the .npy image").
    big_scene = write_scene_json(tmp_path / "big.json", *random_scene(3, 30, 30, (4000, 3000)),
                                 size=(4000, 3000))
    path = tmp_path / "big.npy"
    with open(path, "wb") as f:
        header = "{'descr': '|u1', 'fortran_order': False, 'shape': (3000, 4000, 3), }"
        header += " " * ((64 - (10 + len(header) + 1) % 64) % 64) + "\n"
        f.write(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode())
        f.truncate(f.tell() + 3000 * 4000 * 3)
    monkeypatch.setenv("SCANTRACE_MAX_MEMORY", "64M")
    with pytest.raises(scantrace.InputError, match="decoding the 4000x3000 image needs about"):
        scantrace.diff(big_scene, path)
