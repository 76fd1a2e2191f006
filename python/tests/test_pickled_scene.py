"""The course's own hw1.npy (a pickled dict of four numpy arrays) read by the restricted C++ reader
(io/pickle_reader.cpp) that load_scene and `scantrace render` share: the real file when it is
here, pickles made here with Python's pickle (protocols 2-5), and hostile pickles, each refused in
one line that names the file, with nothing run."""

import io
import os
import pathlib
import pickle
import subprocess

import numpy as np
import pytest

import scantrace
from conftest import SCANTRACE, SHARED_DATA

COURSE_NPY = SHARED_DATA / "hw1_2024.npy"
COURSE_JSON = SHARED_DATA / "hw1_2024.json"


def small_scene(**dtypes):
    """A 3-face scene as the course stores it (int64 vertices and faces, float32 colours and
    depth), with dtypes replaced as asked."""
    d = {"vertices": np.array([[10, 10], [100, 20], [40, 90], [120, 120], [5, 200]], np.int64),
         "vcolors": np.linspace(0, 1, 15, dtype=np.float32).reshape(5, 3),
         "faces": np.array([[0, 1, 2], [1, 2, 3], [2, 3, 4]], np.int64),
         "depth": np.array([3, 1, 2, 5, 4], np.float32)}
    for key, dt in dtypes.items():
        d[key] = d[key].astype(dt)
    return d


def npy_bytes(obj, protocol):
    """What np.save writes for a dict (a 0-d object array, pickled), at `protocol`."""
    holder = np.empty((), dtype=object)
    holder[()] = obj
    f = io.BytesIO()
    np.lib.format.write_array_header_1_0(f, {"descr": "|O", "fortran_order": False, "shape": ()})
    f.write(pickle.dumps(holder, protocol=protocol))
    return f.getvalue()


def expected(d):
    """The scene the file should give, computed here from the arrays."""
    return (np.asarray(d["vertices"], float), np.asarray(d["faces"], np.int64),
            np.asarray(d["vcolors"], float), np.asarray(d["depth"], float).reshape(-1))


def assert_scene(loaded, d):
    v, f, c, z = expected(d)
    np.testing.assert_array_equal(loaded["vertices"], v)
    np.testing.assert_array_equal(loaded["faces"], f)
    np.testing.assert_array_equal(loaded["vcolors"], c)
    np.testing.assert_array_equal(loaded["depth"], z)
    assert loaded["size"] == (512, 512)
    assert loaded["background"] == (1.0, 1.0, 1.0)


def test_the_course_file_is_the_course_json_scene():
    if not COURSE_NPY.exists() or not COURSE_JSON.exists():
        pytest.skip(f"{COURSE_NPY} is not here")
    a = scantrace.load_scene(COURSE_NPY)
    b = scantrace.load_scene(COURSE_JSON)
    for key in ("vertices", "faces", "vcolors", "depth"):
        np.testing.assert_array_equal(a[key], b[key])
    # And as numpy's own unpickler reads it (trusted here: it is the course's file).
    d = np.load(COURSE_NPY, allow_pickle=True).item()
    assert_scene(a, d)


def test_the_command_renders_the_course_file_as_the_json_scene(tmp_path):
    if not COURSE_NPY.exists() or not COURSE_JSON.exists():
        pytest.skip(f"{COURSE_NPY} is not here")
    for scene in (COURSE_NPY, COURSE_JSON):
        subprocess.run([SCANTRACE, "render", str(scene), "-o", str(tmp_path / f"{scene.suffix}.png")],
                       check=True, capture_output=True)
    assert (tmp_path / ".npy.png").read_bytes() == (tmp_path / ".json.png").read_bytes()


@pytest.mark.parametrize("protocol", [2, 3, 4, 5])
@pytest.mark.parametrize("wrapped", [True, False], ids=["np.save", "pickle.dumps"])
def test_pickles_of_every_protocol(tmp_path, protocol, wrapped):
    d = small_scene()
    path = tmp_path / "scene.npy"
    path.write_bytes(npy_bytes(d, protocol) if wrapped else pickle.dumps(d, protocol=protocol))
    assert_scene(scantrace.load_scene(path), d)


@pytest.mark.parametrize("dtypes", [
    {"vertices": np.float64, "depth": np.float64, "vcolors": np.float64},
    {"faces": np.int32, "vertices": np.int16},
    {"faces": np.uint8, "depth": np.int64},
    {"vertices": ">f8", "vcolors": ">f4", "faces": ">i8", "depth": ">f4"},
], ids=["float64", "narrow ints", "unsigned", "big-endian"])
def test_other_numeric_dtypes_keep_their_values(tmp_path, dtypes):
    d = small_scene(**dtypes)
    path = tmp_path / "scene.npy"
    path.write_bytes(npy_bytes(d, 3))
    assert_scene(scantrace.load_scene(path), d)


def test_fortran_order_and_a_column_of_depths(tmp_path):
    d = small_scene()
    d["vertices"] = np.asfortranarray(d["vertices"])
    d["depth"] = d["depth"].reshape(-1, 1)
    path = tmp_path / "scene.npy"
    path.write_bytes(npy_bytes(d, 2))
    assert_scene(scantrace.load_scene(path), d)


def test_render_of_the_pickle_equals_render_of_the_arrays(tmp_path):
    d = small_scene()
    path = tmp_path / "scene.npy"
    path.write_bytes(npy_bytes(d, 4))
    v, f, c, z = expected(d)
    np.testing.assert_array_equal(scantrace.render(**scantrace.load_scene(path)),
                                  scantrace.render(v, f, c, z))


class RunsACommand:
    """What a malicious pickle does: unpickling calls os.system."""

    def __init__(self, marker):
        self.marker = marker

    def __reduce__(self):
        return (os.system, (f"touch {self.marker}",))


def hostile(tmp_path):
    """name -> (bytes, a fragment the one-line refusal must hold)."""
    marker = tmp_path / "pwned"
    evil = {**small_scene(), "faces": RunsACommand(marker)}
    nested = []
    for _ in range(100):
        nested = [nested]
    return marker, {
        "os.system by REDUCE (np.save)": (npy_bytes(evil, 3), "global 'posix.system' is refused"),
        "os.system by REDUCE (bare)": (pickle.dumps(RunsACommand(marker), protocol=2),
                                       "global 'posix.system' is refused"),
        "os.system by STACK_GLOBAL": (pickle.dumps(evil, protocol=4),
                                      "global 'posix.system' is refused"),
        "builtins.eval": (b"\x80\x02cbuiltins\neval\nX\x04\x00\x00\x001+1q\x00\x85R.",
                          "global 'builtins.eval' is refused"),
        "numpy.load": (b"\x80\x02cnumpy\nload\nX\x01\x00\x00\x00x\x85R.",
                       "global 'numpy.load' is refused"),
        "deep nesting": (pickle.dumps({"vertices": nested}, protocol=2), "nest deeper than"),
        "many marks": (b"\x80\x02" + b"(" * 10000 + b".", "nested too deeply"),
        "huge BINBYTES8": (b"\x80\x04\x8e" + (2 ** 62).to_bytes(8, "little") + b".",
                           "only 1 are left in the file"),
        "huge BINUNICODE": (b"\x80\x02X\xff\xff\xff\x7f.", "are left in the file"),
        "huge shape": (pickle.dumps(small_scene(), protocol=2).replace(
            b"K\x05K\x02\x86", b"\x8a\x05\x00\x00\x00\x00\x01\x8a\x05\x00\x00\x00\x00\x01\x86"),
            "shape declares more elements"),
        "truncated": (npy_bytes(small_scene(), 3)[:-40], "pickle byte"),
        "text protocol 0": (pickle.dumps(small_scene(), protocol=0),
                            "neither a .npy file nor a pickle of protocol 2"),
        "a list, not a dict": (npy_bytes([1, 2], 3), "not a dict of numpy arrays"),
        "an object array inside": (npy_bytes({**small_scene(), "depth": np.array([None] * 5)}, 3),
                                   "'depth' is an object array"),
        "an extra key": (npy_bytes({**small_scene(), "size": np.array([512, 512])}, 3),
                         "size: is not a key of the course's scene"),
        "a missing key": (npy_bytes({k: v for k, v in small_scene().items() if k != "depth"}, 3),
                          "missing key 'depth'"),
        "int colours": (npy_bytes(small_scene(vcolors=np.int64), 3), "vcolors: dtype <i8 is not a float"),
        "NaN depth": (npy_bytes({**small_scene(), "depth": np.array([1, np.nan, 2, 3, 4])}, 3),
                      "depth[1]: NaN"),
        "index out of range": (npy_bytes({**small_scene(), "faces": np.array([[0, 1, 9]])}, 3),
                               "faces[0]: vertex index 9 is out of range (5 vertices)"),
        "index 2^64 - 1": (npy_bytes({**small_scene(),
                                      "faces": np.array([[0, 1, 2 ** 64 - 1]], np.uint64)}, 3),
                           "vertex index 18446744073709551615 is out of range"),
        "a plain image .npy": (b"", "holds a plain array"),
    }


def plain_image_npy():
    f = io.BytesIO()
    np.save(f, np.zeros((4, 4, 3)))
    return f.getvalue()


@pytest.mark.parametrize("case", list(hostile(pathlib.Path("/nonexistent"))[1]))
def test_hostile_pickles_are_refused_in_one_line_and_run_nothing(tmp_path, case):
    marker, cases = hostile(tmp_path)
    data, fragment = cases[case]
    if case == "a plain image .npy":
        data = plain_image_npy()
    path = tmp_path / "evil.npy"
    path.write_bytes(data)
    with pytest.raises(scantrace.InputError) as e:
        scantrace.load_scene(path)
    message = str(e.value)
    assert message.startswith(str(path) + ": ")
    assert fragment in message, message
    assert "\n" not in message and len(message) < 400
    # The command line shares the reader: exit 1, the same line, no output file.
    r = subprocess.run([SCANTRACE, "render", str(path), "-o", str(tmp_path / "out.png")],
                       capture_output=True, text=True)
    assert r.returncode == 1
    assert fragment in r.stderr and r.stderr.count("\n") == 1, r.stderr
    assert not (tmp_path / "out.png").exists()
    assert not marker.exists()
