"""Bad input: a TypeError or ValueError naming the argument, what was expected and what was
given; nothing crashes the interpreter."""

import subprocess
import sys
import textwrap

import numpy as np
import pytest

import scantrace

TRI = [[20, 20], [250, 80], [300, 400]]
RGB = np.eye(3)


def scene(**change):
    s = dict(vertices=np.array([[0, 0], [10, 0], [0, 10], [10, 10]], float),
             faces=np.array([[0, 1, 2], [1, 3, 2]]), vcolors=np.full((4, 3), 0.5),
             depth=np.arange(4.0))
    s.update(change)
    return s


@pytest.mark.parametrize("call, error, message", [
    (lambda: scantrace.f_shading(np.ones((9, 9, 3)), [[1, 2, 3], [4, 5, 6]], RGB), ValueError,
     "vertices: expected an array of shape (3, 2), got (2, 3)"),
    (lambda: scantrace.g_shading(np.ones((9, 9, 3)), TRI, np.eye(4)), ValueError,
     "vcolors: expected an array of shape (3, 3), got (4, 4)"),
    (lambda: scantrace.g_shading(np.ones((9, 9)), TRI, RGB), ValueError,
     "img: expected an array of shape (M, N, 3), got (9, 9)"),
    (lambda: scantrace.g_shading(np.ones((9, 9, 3), int), TRI, RGB), TypeError,
     "img: expected a float32 or float64 array, got dtype int64"),
    (lambda: scantrace.g_shading([[0.0] * 3] * 4, TRI, RGB), TypeError,
     "img: expected a numpy array of shape (M, N, 3) to fill in place, got list"),
    (lambda: scantrace.g_shading(np.ones((9, 9, 3)), [["a", "b"]] * 3, RGB), TypeError,
     "vertices: expected an array of numbers (float or int), got dtype <U1"),
    (lambda: scantrace.g_shading(np.ones((9, 9, 3)), [[np.nan, 0], [1, 1], [2, 0]], RGB),
     ValueError, "vertices[0]: NaN and infinity are not allowed, got nan"),
    (lambda: scantrace.g_shading(np.ones((9, 9, 3)), TRI, [[0, 0, 0], [0, np.inf, 0], [1, 1, 1]]),
     ValueError, "vcolors[1]: NaN and infinity are not allowed, got inf"),
    (lambda: scantrace.g_shading(np.ones((9, 9, 3)), TRI, [[0, 0, 0], [0, 2, 0], [1, 1, 1]]),
     ValueError, "vcolors[1]: colour components must be in [0, 1], got 2.0"),
    (lambda: scantrace.render(**scene(faces=np.array([[0, 1, 2], [1, 4, 2]]))), ValueError,
     "faces[1]: vertex index 4 is out of range (4 vertices)"),
    (lambda: scantrace.render(**scene(faces=np.array([[0, 1, 2], [-1, 3, 2]]))), ValueError,
     "faces[1]: vertex index -1 is out of range (4 vertices)"),
    (lambda: scantrace.render(**scene(faces=np.array([[0, 1, 2.0]]))), TypeError,
     "faces: expected an array of integers, got dtype float64"),
    (lambda: scantrace.render(**scene(depth=np.arange(3.0))), ValueError,
     "depth: expected an array of shape (4,), got (3,)"),
    (lambda: scantrace.render(**scene(vcolors=np.full((3, 3), 0.5))), ValueError,
     "vcolors: expected an array of shape (4, 3), got (3, 3)"),
    (lambda: scantrace.render(**scene(depth=np.array([0, 1, np.nan, 3]))), ValueError,
     "depth[2]: NaN and infinity are not allowed, got nan"),
    (lambda: scantrace.render(**scene(), shading="phong"), ValueError,
     "shading: expected 'f', 'g', 'flat' or 'gouraud' (in any case), got 'phong'"),
    (lambda: scantrace.render(**scene(), fill_rule="open"), ValueError,
     "fill_rule: expected 'top-left' or 'closed', got 'open'"),
    (lambda: scantrace.render(**scene(), size=(0, 10)), ValueError,
     "size: expected (width, height), both positive"),
    (lambda: scantrace.render(**scene(), dtype=np.int16), TypeError,
     "dtype: expected float64, float32 or uint8, got int16"),
    (lambda: scantrace.render_img(None, *list(scene().values())[:1], np.full((4, 3), .5),
                                  np.zeros(4), "f"), TypeError,
     "faces: expected an array, got None"),
    (lambda: scantrace.render_img(**{**scene(), "shading": 1}), TypeError,
     "shading: expected 'f' or 'g', got int"),
    (lambda: scantrace.vector_interp([0, 0, 0], [1, 1], 0.0, 1.0, 0.5, 1), ValueError,
     "p1: expected an array of shape (2,), got (3,)"),
    (lambda: scantrace.trace_triangle(TRI, RGB, level="everything"), ValueError,
     "level: expected 'triangle', 'scanline' or 'pixel', got 'everything'"),
    (lambda: scantrace.trace_scene(**scene(), triangles="3-x"), ValueError, "triangles: "),
])
def test_message_names_the_argument(call, error, message):
    with pytest.raises(error) as e:
        call()
    assert message in str(e.value)


def test_bad_files_name_the_file_and_element(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"vertices": [[0,0],[1,0],[0,1]], "vcolors": [[0,0,0],[0,0,0],[0,0,0]],'
                   ' "faces": [[0,1,5]], "depth": [0,0,0]}')
    with pytest.raises(scantrace.InputError, match=r"bad.json: faces\[0\]: vertex index 5"):
        scantrace.load_scene(bad)
    with pytest.raises(ValueError):  # InputError is a ValueError
        scantrace.load_scene(tmp_path / "missing.json")
    (tmp_path / "t.jsonl").write_text('{"type": "header"\n')
    with pytest.raises(ValueError, match=r"t.jsonl:1: not valid JSON"):
        scantrace.Trace.load(tmp_path / "t.jsonl")


def test_query_of_a_missing_row_is_an_index_error():
    t = scantrace.trace_triangle(TRI, RGB)
    with pytest.raises(IndexError, match="row 500 is not filled: triangle 0's rows are"):
        t.scanline(0, 500)
    # A pixel no triangle wrote is not an error: its history is empty and final() is None.
    assert t.pixel_history(5, 5).final() is None


def test_nothing_crashes_the_interpreter():
    # Every call a careless or hostile caller might make, in a fresh interpreter: each must
    # raise a Python exception; a crash would end the process with a signal.
    script = textwrap.dedent("""
        import numpy as np, scantrace, itertools
        values = [None, 1, "x", [], [[]], np.array([]), np.zeros((0, 3)), np.zeros((3, 2, 1)),
                  np.full((3, 2), np.nan), np.full((3, 3), -1.0), np.zeros((3, 2), np.complex128),
                  np.zeros((3, 2), object), np.zeros((3, 3), bool), [[1e308, 1e308]] * 3,
                  np.zeros((2**31 // 8, 0)), np.ones((3, 2))[:, ::-1], np.ones((5, 3), np.int8)]
        calls = [
            lambda a, b: scantrace.f_shading(np.ones((8, 8, 3)), a, b),
            lambda a, b: scantrace.g_shading(a, b, np.eye(3)),
            lambda a, b: scantrace.render_img(a, b, np.ones((3, 3)), np.zeros(3), "g"),
            lambda a, b: scantrace.render(b, [[0, 1, 2]], a, np.zeros(3)),
            lambda a, b: scantrace.vector_interp(a, b, 0.0, 1.0, 0.5, 1),
            lambda a, b: scantrace.trace_triangle(a, b),
            lambda a, b: scantrace.render(np.zeros((3, 2)), [[0, 1, 2]], np.ones((3, 3)), a,
                                          size=b),
        ]
        n = 0
        for call, a, b in itertools.product(calls, values, values):
            try:
                call(a, b)
            except (TypeError, ValueError, IndexError, OverflowError):
                n += 1
        print("raised", n)
    """)
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                       timeout=300)
    assert r.returncode == 0, r.stderr
    assert "raised" in r.stdout
