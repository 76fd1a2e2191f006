"""Issue 37's Python points: arguments a careless or hostile caller passes. Each is refused with
one line naming the argument, or handled right (a big-endian array is filled with the right
values); no call hangs, none ends in an internal error, no message is empty."""

import os
import signal
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import scantrace

TRI = [[20, 20], [250, 80], [300, 400]]
RGB = np.eye(3)


def small_scene():
    return dict(vertices=np.array([[0, 0], [10, 0], [0, 10], [10, 10]], float),
                faces=np.array([[0, 1, 2], [1, 3, 2]]), vcolors=np.full((4, 3), 0.5),
                depth=np.arange(4.0))


@pytest.mark.parametrize("dtype", [">f8", ">f4"])
@pytest.mark.parametrize("fill", ["f_shading", "g_shading"])
def test_big_endian_images_are_filled_with_the_right_values(dtype, fill):
    native = np.ones((512, 512, 3), dtype.replace(">", "<"))
    swapped = np.ones((512, 512, 3), dtype)
    getattr(scantrace, fill)(native, TRI, RGB)
    out = getattr(scantrace, fill)(swapped, TRI, RGB)
    assert out is swapped and swapped.dtype == np.dtype(dtype)
    np.testing.assert_array_equal(swapped, native)
    assert (native != 1).any()


def test_a_face_index_of_2_to_the_64_minus_1_is_named_as_it_is():
    s = small_scene()
    s["faces"] = np.array([[0, 1, 2], [1, 2 ** 64 - 1, 2]], np.uint64)
    with pytest.raises(ValueError, match=r"^faces\[1\]: index 18446744073709551615 is out of range$"):
        scantrace.render(**s)


def test_max_events_beyond_int64_is_a_value_error():
    with pytest.raises(ValueError, match=r"max_events: expected a count in 0 \.\. 2\^63 - 1, got "
                                         r"1180591620717411303424"):
        scantrace.trace_scene(**small_scene(), max_events=2 ** 70)
    with pytest.raises(ValueError, match="max_events: expected a count"):
        scantrace.trace_scene(**small_scene(), max_events=-1)
    with pytest.raises(TypeError, match="max_events: expected an int, got float"):
        scantrace.trace_scene(**small_scene(), max_events=float("nan"))


def test_a_vector_longer_than_int_is_refused_before_any_copy():
    # A broadcast view: 2^31 + 3 rows and no memory behind them.
    huge = np.broadcast_to(np.zeros(2), (2 ** 31 + 3, 2))
    with pytest.raises(ValueError, match=r"vertices: dimension 0 has 2147483651 elements, more "
                                         r"than the 2\^31 - 1 allowed"):
        scantrace.render(huge, np.zeros((0, 3), int), np.zeros((0, 3)), np.zeros(0))


def test_write_png_of_a_huge_strided_array_is_a_clear_error(tmp_path):
    # 16384 x 16384 float64 is 6 GiB once copied: refused under a 500 MB budget, before copying.
    script = textwrap.dedent(f"""
        import numpy as np, scantrace
        img = np.broadcast_to(np.zeros(3), (16384, 16384, 3))
        try:
            scantrace.write_png(img, {str(tmp_path / 'x.png')!r})
        except MemoryError as e:
            print('MemoryError', e)
        except ValueError as e:
            print('ValueError', e)
    """)
    env = {**os.environ, "SCANTRACE_MAX_MEMORY": "500M"}
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env,
                       timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith("ValueError img: writing this PNG needs about"), r.stdout
    assert "Internal error" not in r.stdout + r.stderr
    assert not (tmp_path / "x.png").exists()
    with pytest.raises(ValueError, match=r"img: image of 20000x20000 pixels is too large"):
        scantrace.write_png(np.broadcast_to(np.zeros(3), (20000, 20000, 3)), tmp_path / "y.png")


def test_trace_load_of_a_directory(tmp_path):
    with pytest.raises(scantrace.InputError, match=f"^{tmp_path}: is a directory, not a trace"):
        scantrace.Trace.load(tmp_path)


def test_load_scene_reads_mat_files_as_mat(tmp_path):
    fake = tmp_path / "x.mat"
    fake.write_text('{"vertices": []}')
    with pytest.raises(scantrace.InputError) as e:
        scantrace.load_scene(fake)
    assert "JSON" not in str(e.value) and str(e.value).startswith(str(fake))


@pytest.mark.parametrize("name", ["two_triangles_v5.mat", "two_triangles_v5_zlib.mat"])
def test_load_scene_of_a_mat_file_renders_as_the_command(tmp_path, name):
    from conftest import SCANTRACE, SOURCE_DIR
    PIL = pytest.importorskip("PIL.Image")
    path = SOURCE_DIR / "fuzz" / "corpus" / "mat_scene" / name
    s = scantrace.load_scene(path)
    assert s["faces"].tolist() == [[0, 1, 2], [1, 3, 2]]  # MATLAB's 1-based faces, 0-based here
    subprocess.run([SCANTRACE, "render", str(path), "-o", str(tmp_path / "m.png")], check=True,
                   capture_output=True)
    np.testing.assert_array_equal(scantrace.render(**s, dtype=np.uint8),
                                  np.asarray(PIL.open(tmp_path / "m.png").convert("RGB")))


def test_load_scene_refuses_a_v73_mat_file_as_the_command_does(tmp_path):
    # HDF5 (v7.3) is not read anywhere: the same one line from Python as from the command.
    from conftest import SCANTRACE, SOURCE_DIR
    path = SOURCE_DIR / "fuzz" / "corpus" / "mat_scene" / "two_triangles_v73.mat"
    with pytest.raises(scantrace.InputError) as e:
        scantrace.load_scene(path)
    assert str(e.value) == f"{path}: is a MATLAB v7.3 (HDF5) file, which scantrace does not read " \
        "(HDF5 is not safe on untrusted files); re-save it as v7: save('scene.mat', ..., '-v7')"
    r = subprocess.run([SCANTRACE, "render", str(path), "-o", str(tmp_path / "m.png")],
                       capture_output=True, text=True)
    assert r.returncode == 1 and r.stderr.strip().endswith(str(e.value))


def test_rows_and_triangles_that_select_nothing_are_refused_as_the_command_does():
    s = small_scene()
    with pytest.raises(ValueError, match=r"rows: expected \(first, last\) with first <= last, "
                                         r"got \(10, 5\)"):
        scantrace.trace_scene(**s, rows=(10, 5))
    with pytest.raises(ValueError, match=r"rows: \(600, 700\) selects no row of the canvas"):
        scantrace.trace_scene(**s, rows=(600, 700))
    with pytest.raises(ValueError, match=r"triangles: '5' selects no face: the scene has 2 faces"):
        scantrace.trace_scene(**s, triangles="5")
    with pytest.raises(ValueError, match=r"triangles: '7,9' selects no face"):
        scantrace.trace_scene(**s, triangles=[7, 9])
    assert scantrace.trace_scene(**s, triangles="1").triangles() == [1]


NAN_INF = [float("nan"), float("inf"), -float("inf")]


def with_one(a, x):
    """A copy of `a` whose first element is x."""
    b = np.array(a, float)
    b.flat[0] = x
    return b


def numeric_arguments():
    """Every float argument of the package, as a call taking the bad value."""
    s = small_scene()
    img = lambda: np.ones((32, 32, 3))  # noqa: E731
    return {
        "vector_interp coord": lambda x: scantrace.vector_interp([0, 0], [1, 1], 0, 1, x, 1),
        "vector_interp p1": lambda x: scantrace.vector_interp([x, 0], [1, 1], 0, 1, 0.5, 1),
        "vector_interp V1": lambda x: scantrace.vector_interp([0, 0], [1, 1], x, 1, 0.5, 1),
        "f_shading vertices": lambda x: scantrace.f_shading(img(), [[x, 0], [1, 1], [2, 0]], RGB),
        "g_shading vcolors": lambda x: scantrace.g_shading(img(), TRI, [[x, 0, 0], [0, 0, 0],
                                                                         [0, 0, 0]]),
        "render vertices": lambda x: scantrace.render(**{**s, "vertices": with_one(s["vertices"], x)}),
        "render depth": lambda x: scantrace.render(**{**s, "depth": with_one(s["depth"], x)}),
        "render vcolors": lambda x: scantrace.render(**{**s, "vcolors": with_one(s["vcolors"], x)}),
        "render background": lambda x: scantrace.render(**s, background=(x, 0, 0)),
        "render size": lambda x: scantrace.render(**s, size=(x, 10)),
        "render_img depth": lambda x: scantrace.render_img(s["faces"], s["vertices"],
                                                           s["vcolors"], with_one(s["depth"], x),
                                                           "g"),
        "trace_triangle vertices": lambda x: scantrace.trace_triangle([[x, 0], [1, 1], [2, 0]],
                                                                      RGB),
        "trace_triangle background": lambda x: scantrace.trace_triangle(TRI, RGB,
                                                                        background=(0, x, 0)),
        "trace_scene depth": lambda x: scantrace.trace_scene(**{**s, "depth": with_one(s["depth"], x)}),
        "trace_scene max_events": lambda x: scantrace.trace_scene(**s, max_events=x),
        "trace_scene rows": lambda x: scantrace.trace_scene(**s, rows=(0, x)),
        "write_png img": lambda x: scantrace.write_png(np.full((4, 4, 3), x), "/nonexistent/x.png"),
        "why x": lambda x: scantrace.why((s["faces"], s["vertices"], s["vcolors"], s["depth"]),
                                         x, 0),
        "diff tolerance": lambda x: scantrace.diff((s["faces"], s["vertices"], s["vcolors"],
                                                    s["depth"]), np.ones((512, 512, 3)),
                                                   tolerance=x),
        "diff image": lambda x: scantrace.diff((s["faces"], s["vertices"], s["vcolors"],
                                                s["depth"]), np.full((512, 512, 3), x)),
    }


@pytest.mark.parametrize("name", list(numeric_arguments()))
@pytest.mark.parametrize("bad", NAN_INF, ids=["nan", "inf", "-inf"])
def test_every_numeric_argument_refuses_nan_and_infinity(name, bad):
    with pytest.raises((ValueError, TypeError)) as e:
        numeric_arguments()[name](bad)
    message = str(e.value)
    assert message.strip() and "\n" not in message, repr(message)
    assert "Internal error" not in message and "Unable to cast" not in message


def test_explain_refuses_nan_frame_rates(tmp_path):
    pytest.importorskip("scantrace._scantrace_cv")
    for fps in NAN_INF + [0.0]:
        with pytest.raises(ValueError, match="fps: expected a positive number"):
            scantrace.explain(TRI, RGB, out=tmp_path / "x/", fps=fps)
    for hold in NAN_INF:
        with pytest.raises(ValueError, match="hold: expected a time in seconds"):
            scantrace.explain(TRI, RGB, out=tmp_path / "x/", hold=hold)


def run_with_timeout(code, timeout=20):
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=timeout)


# Issue 37 point 5: the C++ readers open inputs without blocking and refuse what is not a regular
# file (io/input_file.hpp); before that a reader blocked in open() on a FIFO and this timed out.
@pytest.mark.parametrize("call", ["scantrace.load_scene(p)", "scantrace.Trace.load(p)"])
def test_a_fifo_is_refused_not_waited_on(tmp_path, call):
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    code = (f"import scantrace\np = {str(fifo)!r}\ntry:\n    {call}\n"
            "except ValueError as e:\n    print('refused:', e)\n")
    try:
        r = run_with_timeout(code, timeout=10)
    except subprocess.TimeoutExpired:
        pytest.fail(f"{call} on a FIFO blocked for 10 s")
    assert r.stdout.startswith(f"refused: {fifo}"), r.stdout + r.stderr


def test_ctrl_c_interrupts_a_long_render():
    # 10^6 identical faces over the canvas: seconds of work; SIGINT after half a second.
    code = textwrap.dedent("""
        import sys, time, numpy as np, scantrace
        n = 1_000_000
        v = np.array([[0, 0], [2048, 0], [0, 2048]], float)
        faces = np.zeros((n, 3), np.int64); faces[:] = [0, 1, 2]
        c, z = np.eye(3), np.zeros(3)
        print('ready', flush=True)
        t = time.monotonic()
        try:
            scantrace.render(v, faces, c, z, size=(2048, 2048), shading='flat')
            print('finished', time.monotonic() - t)
        except KeyboardInterrupt:
            print('interrupted', time.monotonic() - t)
    """)
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "ready"
    import time
    time.sleep(0.5)
    p.send_signal(signal.SIGINT)
    out, _ = p.communicate(timeout=60)
    word, seconds = out.split()
    if word == "finished":
        pytest.skip(f"the render finished in {seconds} s, before the signal")
    assert word == "interrupted" and float(seconds) < 2.0, out


def bad_files(tmp_path):
    """Files a careless caller hands to the readers, by name."""
    files = {
        "empty": b"",
        "garbage": bytes(range(256)) * 4,
        "empty JSON object": b"{}",
        "truncated JSON": b'{"vertices": [[0, 0], [1',
        "npy magic only": b"\x93NUMPY",
        "pickle opcode only": b"\x80\x04",
        "trace header only": b'{"type":"header"}\n',
    }
    out = {}
    for name, data in files.items():
        p = tmp_path / (name.replace(" ", "_") + ".npy")
        p.write_bytes(data)
        out[name] = p
    return out


def test_no_error_message_is_empty(tmp_path):
    """Every refusal of a bad file says something (the course's hw1.npy once raised InputError()
    with an empty message), in one line that names the file."""
    files = bad_files(tmp_path)
    calls = []
    for name, p in files.items():
        calls += [(f"load_scene({name})", lambda p=p: scantrace.load_scene(p)),
                  (f"Trace.load({name})", lambda p=p: scantrace.Trace.load(p)),
                  (f"check({name})", lambda p=p: scantrace.check(p)),
                  (f"diff image ({name})", lambda p=p: scantrace.diff(
                      (small_scene()["faces"], small_scene()["vertices"],
                       small_scene()["vcolors"], small_scene()["depth"]), p))]
    calls += [("load_scene(missing)", lambda: scantrace.load_scene(tmp_path / "missing.json")),
              ("load_scene(directory)", lambda: scantrace.load_scene(tmp_path))]
    for what, call in calls:
        try:
            result = call()
        except Exception as e:  # noqa: BLE001: every kind of refusal is looked at
            message = str(e)
            assert message.strip(), f"{what}: {type(e).__name__} with an empty message"
            assert "\n" not in message, f"{what}: {message!r}"
        else:
            # check() gives its verdict as a result: then the problem is the message.
            assert isinstance(result, scantrace.CheckResult) and result.problem.strip(), what
