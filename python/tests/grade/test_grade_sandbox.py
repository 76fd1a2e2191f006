"""Hostile submissions, each written here: the verdict is right, the other calls still run, the
report is written, and the grader's own files cannot be read from inside the sandbox."""

import json
import os
import pathlib
import tempfile
import textwrap

import numpy as np
import pytest

from scantrace.grade import __main__ as cli
from scantrace.grade.sandbox import Limits, Session
from scantrace.grade.submission import stage

from conftest import CORRECT, grade_source, write_submission

HOSTILE = textwrap.dedent('''\
    import numpy as np

    def f_shading(img, vertices, vcolors):
        mode = int(vertices[0][0])
        if mode == 1:
            while True:
                pass
        if mode == 2:
            x = np.ones(int(6e9))          # 48 GB
        if mode == 3:
            import os
            while True:
                os.fork()
        if mode == 4:
            import socket
            socket.socket().connect(("1.1.1.1", 80))
        if mode == 5:
            return open(SECRET).read()
        if mode == 6:
            print("x" * 100_000_000)       # 100 MB
        if mode == 7:
            import ctypes
            ctypes.string_at(0)            # the interpreter crashes
        if mode == 8:
            open("/usr/evil", "w")
        img[1, 1] = 0.5
        return img
    ''')

EXPECTED = {0: "ok", 1: "timeout", 2: "memory", 3: "forbidden", 4: "forbidden", 5: "forbidden",
            6: "forbidden", 7: "crashed", 8: "forbidden", 9: "ok"}


@pytest.mark.parametrize("sandbox", [True, False])
def test_each_hostile_call_gets_its_verdict_and_the_rest_run(tmp_path, sandbox_ok, sandbox):
    # A grader's file outside /tmp: inside the sandbox /tmp is a private tmpfs, where the path of
    # a file planted under the host's /tmp is merely absent (`error`), not `forbidden`.
    base = pathlib.Path(os.environ.get("SCANTRACE_BUILD_DIR", tmp_path)).resolve()
    if base.is_relative_to(pathlib.Path(tempfile.gettempdir()).resolve()):
        base = pathlib.Path.home()
    secret = base / f"grader-secret-{os.getpid()}.txt"
    secret.write_text("THE-HIDDEN-SEED-IS-42")
    try:
        sub = stage(write_submission(tmp_path / "hostile",
                                     f"SECRET = {str(secret)!r}\n" + HOSTILE))
        session = Session(sub.root, sub.functions,
                          Limits(call_seconds=1.0, memory_mb=1024), sandbox=sandbox)
        calls = []
        for mode in EXPECTED:
            v = session.input(np.array([[mode % 9, 0], [5, 0], [0, 5]]))
            c = session.input(np.eye(3))
            calls.append({"id": f"m{mode}", "kind": "call", "func": "f_shading",
                          "args": [0, {"npy": v}, {"npy": c}], "canvas": 0,
                          "canvas_shape": [4, 4, 3]})
        results = session.run(calls)
        session.close()
        sub.close()
    finally:
        secret.unlink()
    got = {int(k[1:]): r.status for k, r in results.items()}
    assert got == EXPECTED
    assert "the output limit" in results["m6"].detail and "xxxx" in results["m6"].detail
    assert "open a socket" in results["m4"].detail
    assert str(secret) in results["m5"].detail
    for r in results.values():
        assert "THE-HIDDEN-SEED" not in r.detail
    assert results["m0"].value[1, 1].tolist() == [0.5, 0.5, 0.5]


def test_without_the_sandbox_the_student_reads_no_other_temporary_file(tmp_path):
    # --no-sandbox has only the audit hook: it must allow the session's own folder, not the whole
    # of /tmp, where other sessions' submissions and the grader's temporary files lie (it allowed
    # /tmp/ whole, and a file planted there was read).
    secret = pathlib.Path(tempfile.gettempdir()) / f"grader-tmp-secret-{os.getpid()}.txt"
    secret.write_text("THE-HIDDEN-SEED-IS-42")
    try:
        sub = stage(write_submission(tmp_path / "hostile",
                                     f"SECRET = {str(secret)!r}\n" + HOSTILE))
        session = Session(sub.root, sub.functions, Limits(call_seconds=1.0, memory_mb=1024),
                          sandbox=False)
        v = session.input(np.array([[5, 0], [5, 0], [0, 5]]))
        c = session.input(np.eye(3))
        results = session.run([{"id": "m5", "kind": "call", "func": "f_shading",
                                "args": [0, {"npy": v}, {"npy": c}], "canvas": 0,
                                "canvas_shape": [4, 4, 3]}])
        session.close()
        sub.close()
    finally:
        secret.unlink()
    assert results["m5"].status == "forbidden"
    assert str(secret) in results["m5"].detail


def test_planted_grader_files_are_not_there_inside(tmp_path, sandbox_ok):
    # A planted file and a hidden scene beside the grader's output, in /tmp (where the student's
    # own /tmp is a private, empty one): the student's code looks for them and reports.
    planted = tmp_path / "grader" / "rubric-secret.txt"
    planted.parent.mkdir()
    planted.write_text("PLANTED")
    np.save(tmp_path / "grader" / "hidden_scene.npy", np.arange(6.0))
    spy = CORRECT.replace("def f_shading(img, vertices, vcolors):", textwrap.dedent(f'''\
        def _spy():
            import os
            found = [p for p in ({str(planted)!r}, {str(tmp_path / "grader" / "hidden_scene.npy")!r})
                     if os.path.exists(p)]
            if found:
                raise RuntimeError("LEAK " + open(found[0], "rb").read(20).hex())


        def f_shading(img, vertices, vcolors):
            _spy()''').rstrip("\n"), 1)
    graded = grade_source(tmp_path, spy, hidden_seed=None)
    text = (tmp_path / "student-out" / "results.json").read_text()
    assert "LEAK" not in text and "PLANTED" not in text
    assert graded.score == graded.max_score   # nothing found: the student's code ran normally


@pytest.mark.parametrize("exit_call, detail", [("sys.exit(3)", "sys.exit(3)"),
                                               ("os._exit(0)", "exited with status 0")])
def test_exit_at_import_is_a_crash_and_a_report_is_written(tmp_path, sandbox_ok, exit_call,
                                                           detail):
    sub = write_submission(tmp_path / "quitter", "import os, sys\nprint('bye')\n" + exit_call
                           + "\n" + CORRECT)
    out = tmp_path / "out"
    assert cli.main([str(sub), "-o", str(out), "--quiet", "--call-seconds", "2"]) == 0
    results = json.loads((out / "results.json").read_text())
    assert results["score"] == 0
    assert {t["extra_data"]["verdict"] for t in results["tests"]} == {"crashed"}
    assert detail in results["tests"][0]["output"]
    assert (out / "report.md").exists() and (out / "report.html").exists()


def test_refuses_without_namespaces_unless_no_sandbox(tmp_path, monkeypatch, capsys):
    sub = write_submission(tmp_path / "s", CORRECT)
    monkeypatch.setenv("PATH", str(tmp_path / "no-bwrap-here"))
    assert cli.main([str(sub), "-o", str(tmp_path / "out"), "--quiet"]) == 1
    err = capsys.readouterr().err
    assert "refusing to run student code without a sandbox" in err and "bwrap" in err
    assert "--no-sandbox" in err
    assert not (tmp_path / "out").exists()
    assert cli.main([str(sub), "-o", str(tmp_path / "out"), "--quiet", "--no-sandbox",
                     "--call-seconds", "2"]) == 0
    # No hidden scene: the rubric's total all the same (docs/grading.md, "The rubric").
    assert json.loads((tmp_path / "out" / "results.json").read_text())["score"] == 100
