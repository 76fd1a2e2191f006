"""Issue 46's hostile submissions, each written here: the student's code switches the audit hook
off (`__main__._state["armed"] = False`, one line) and attacks the result channel, the staging,
the limits, the reports and class mode. Each gets a verdict, a results.json under 100 KB, and
nothing of the grader's leaks, hangs or crashes."""

import csv
import html.parser
import json
import os
import pathlib
import re
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import textwrap
import threading
import time
import zipfile

import numpy as np
import pytest

from scantrace.grade import __main__ as cli
from scantrace.grade import classmode
from scantrace.grade.sandbox import Limits, Session
from scantrace.grade.submission import stage

from conftest import CORRECT, write_submission

PACKAGE = str(pathlib.Path(cli.__file__).parents[2])   # the folder holding scantrace/

# Helpers a hostile student writes: the hook off, the result pipe's descriptor (the spec names it;
# /proc/self/fd would do too), a record in the channel's format.
FORGE = textwrap.dedent('''\
    import json, os, sys
    import __main__


    def _channel():
        __main__._state["armed"] = False
        return json.load(open(sys.argv[-1]))["result_fd"]


    def _record(header, payload=b""):
        data = json.dumps(header).encode()
        return len(data).to_bytes(4, "big") + data + payload
    ''')

CHANNEL_ATTACKS = FORGE + textwrap.dedent('''\

    def f_shading(img, vertices, vcolors):
        mode = int(vertices[0][0])
        me = f"m{mode}"
        if mode == 1:   # plant a FIFO where the grader used to read m1.bin
            fd = _channel()
            os.mkfifo(os.path.join(__main__._state["out_dir"], "m1.bin"))
        if mode == 2:   # a header length of 4 GiB
            os.write(_channel(), b"\\xff\\xff\\xff\\xff")
            os._exit(0)
        if mode == 3:   # a forged end: 8192 x 8192 x 3 declared (1.5 GiB), nothing sent
            os.write(_channel(), _record({"event": "end", "call": me, "status": "ok",
                                          "shape": [8192, 8192, 3]}))
            os._exit(0)
        if mode == 4:   # the result of a call not yet run (m9), zeros
            os.write(_channel(), _record({"event": "end", "call": "m9", "status": "ok",
                                          "shape": [4, 4, 3]}, bytes(8 * 48)))
            os._exit(0)
        if mode == 5:   # a flood of zeros (/dev/zero into the pipe)
            fd = _channel()
            while True:
                os.write(fd, bytes(65536))
        if mode == 6:   # a header nested 30,000 deep (json's recursion)
            os.write(_channel(), (30000).to_bytes(4, "big") + b"[" * 30000)
            os._exit(0)
        if mode == 7:   # the value of a call that is a FIFO-sized lie: shape says 48, 8 bytes sent
            os.write(_channel(), _record({"event": "end", "call": me, "status": "ok",
                                          "shape": [4, 4, 3]}, bytes(8)))
            os._exit(0)
        if mode == 10:  # not an attack: an honest exception with a 10 MB message
            raise ValueError("x" * 10_000_000)
        img[1, 1] = 0.5
        return img
    ''')

CHANNEL_EXPECTED = {0: "ok", 1: "error", 2: "forbidden", 3: "forbidden", 4: "forbidden",
                    5: "forbidden", 6: "forbidden", 7: "crashed", 8: "ok", 9: "ok", 10: "error"}


def _mode_calls(session, modes):
    calls = []
    for mode in modes:
        v = session.input(np.array([[mode, 0], [5, 0], [0, 5]]))
        c = session.input(np.eye(3))
        calls.append({"id": f"m{mode}", "kind": "call", "func": "f_shading",
                      "args": [0, {"npy": v}, {"npy": c}], "canvas": 0,
                      "canvas_shape": [4, 4, 3]})
    return calls


@pytest.mark.parametrize("sandbox", [True, False])
def test_forged_records_and_planted_files_are_verdicts(tmp_path, sandbox_ok, sandbox):
    """Issue row 1: a FIFO, a 4 GiB header, a huge declared shape, a call not yet run, a flood,
    a deep header, a short value: each is the verdict of its own call, at once, and the calls
    after it still run (m9's forged zeros are not m9's result)."""
    sub = stage(write_submission(tmp_path / "hostile", CHANNEL_ATTACKS))
    session = Session(sub.root, sub.functions, Limits(call_seconds=2.0, memory_mb=1024),
                      sandbox=sandbox)
    start = time.monotonic()
    try:
        results = session.run(_mode_calls(session, CHANNEL_EXPECTED))
    finally:
        session.close()
        sub.close()
    assert time.monotonic() - start < 60
    got = {int(k[1:]): r.status for k, r in results.items()}
    assert got == CHANNEL_EXPECTED, {k: results[f"m{k}"].detail for k in got}
    # The sandbox's /out is a read-only bind; without it the child's uid may not write there.
    assert ("Read-only file system" if sandbox else "Permission denied") in results["m1"].detail
    assert "4294967295 bytes" in results["m2"].detail
    assert "more than the 4096 numbers" in results["m3"].detail
    assert "'end' 'm9' where end of 'm4' was due" in results["m4"].detail
    assert results["m9"].value[1, 1].tolist() == [0.5, 0.5, 0.5]
    assert results["m8"].value[1, 1].tolist() == [0.5, 0.5, 0.5]
    assert "xxxx" in results["m10"].detail and len(results["m10"].detail) <= 4000


SECRET_TEXT = "ROOT-ONLY-SECRET-1234"


def _grade(paths, out, *extra, jobs=1):
    return cli.main([*map(str, paths), "-o", str(out), "--quiet", "--call-seconds", "2",
                     "--jobs", str(jobs), *extra])


def _results(out):
    text = (out / "results.json").read_text()
    assert len(text.encode()) <= 100_000
    return text, json.loads(text)


def test_staging_copies_regular_files_only(tmp_path, sandbox_ok):
    """Issue rows 2 and 5: a symlinked .py to a root-only file, a FIFO named zz.py, a folder
    named pkg.py/, a 10 KB and a 200 KB expression: staged or not, the submission is graded and
    nothing of the secret comes back."""
    secret = tmp_path / "secret.txt"   # a root-only file of the grader's
    secret.write_text(SECRET_TEXT)
    secret.chmod(0o600)
    sub = write_submission(tmp_path / "s", CORRECT)
    os.symlink(secret, sub / "shadow.py")
    os.mkfifo(sub / "zz.py")
    (sub / "pkg.py").mkdir()
    (sub / "pkg.py" / "extra.py").write_text("import os\nos._exit(3)\n")
    (sub / "deep10k.py").write_text("x = " + "+".join(["1"] * 5000) + "\n")
    (sub / "deep200k.py").write_text("x = " + "-" * 200_000 + "1\n")
    os.link(secret, sub / "hard.py")          # a hard link: a regular file, another's
    deep = sub.joinpath(*["d"] * 40)
    deep.mkdir(parents=True)
    (deep / "deepest.py").write_text("import os\nos._exit(3)\n")
    out = tmp_path / "out"
    assert _grade([sub], out) == 0
    text, results = _results(out)
    assert SECRET_TEXT not in text
    notes = "\n".join(results["extra_data"]["notes"])
    assert "shadow.py: a symbolic link, not staged" in notes
    assert "zz.py: not a regular file, not staged" in notes
    assert "pkg.py/: a folder named like a module, not staged" in notes
    assert "deep10k.py: cannot be parsed (RecursionError" in notes
    assert "deep200k.py: cannot be parsed (MemoryError" in notes
    assert "hard.py: a hard link (2 names), not staged" in notes
    assert "folders deeper than 32 levels, not staged" in notes
    assert results["score"] == results["extra_data"]["max_score"] == 100


@pytest.mark.parametrize("name", ["hw1.py", "hw1.zip"])
def test_a_fifo_given_as_the_submission_is_refused_at_once(tmp_path, name):
    """Issue row 5: a FIFO named like a submission blocks nothing (O_NONBLOCK, then fstat)."""
    os.mkfifo(tmp_path / name)
    done = []
    thread = threading.Thread(target=lambda: done.append(_grade([tmp_path / name],
                                                                tmp_path / "out")), daemon=True)
    thread.start()
    thread.join(timeout=30)
    assert done == [1]
    _, results = _results(tmp_path / "out")
    assert "not a regular file" in results["output"]


def _zip(path, members):
    with zipfile.ZipFile(path, "w") as z:
        for name, data, mode in members:
            info = zipfile.ZipInfo(name)
            info.external_attr = mode << 16
            z.writestr(info, data)
    return path


@pytest.mark.parametrize("case", ["symlink", "crc", "file_and_folder"])
def test_hostile_zips_get_a_verdict_and_results_json(tmp_path, sandbox_ok, case):
    """Issue rows 2 and 5: a zip's symlink entry (its data: the target's path) is not staged; a
    bad CRC and a zip holding both hw1.py and hw1.py/extra.py give results.json, never a
    traceback."""
    regular = stat.S_IFREG | 0o644
    members = [("hw1.py", CORRECT, regular)]
    if case == "symlink":
        members.append(("shadow.py", "/etc/shadow", stat.S_IFLNK | 0o777))
    if case == "file_and_folder":
        members.append(("hw1.py/extra.py", "import os\nos._exit(3)\n", regular))
    path = _zip(tmp_path / "sub.zip", members)
    if case == "crc":
        data = bytearray(path.read_bytes())
        data[data.index(b"def vector_interp")] ^= 1   # stored, not deflated: one byte flipped
        path.write_bytes(data)
    out = tmp_path / "out"
    status = _grade([path], out)
    text, results = _results(out)
    if case == "crc":
        assert status == 1 and "Bad CRC-32" in results["output"]
        assert results["output"].startswith("Not graded")
        return
    assert status == 0 and results["score"] == 100
    notes = "\n".join(results["extra_data"]["notes"])
    if case == "symlink":
        assert "shadow.py: a symbolic link, not staged" in notes and "root:" not in text
    else:
        assert "hw1.py/extra.py: in a folder named like a module, not staged" in notes


def test_a_zip_of_nested_folders_leaves_no_temporary_folder(tmp_path, monkeypatch):
    """Issue row 12: the staged copy is removed whole, however deep its files lie (a zip's
    a/b/hw1.py made the submission's root a/b, and only a/ was removed)."""
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path / "t"))
    (tmp_path / "t").mkdir()
    path = _zip(tmp_path / "sub.zip", [("a/b/hw1.py", CORRECT, stat.S_IFREG | 0o644)])
    sub = stage(path)
    assert sub.root.name == "b" and (sub.root / "hw1.py").exists()
    sub.close()
    assert list((tmp_path / "t").iterdir()) == []


def test_a_dotted_file_name_scores_full_marks(tmp_path, sandbox_ok):
    """Issue row 6: hw1.final.py is loaded by its path (`import hw1.final` looks for a package);
    the demo at its bottom fails, so the demo-free loader must load it by path too."""
    sub = write_submission(tmp_path / "s", CORRECT, name="hw1.final.py")
    out = tmp_path / "out"
    assert _grade([sub], out) == 0
    _, results = _results(out)
    assert results["score"] == results["extra_data"]["max_score"] == 100


LIMIT_ATTACKS = textwrap.dedent('''\
    import os
    import __main__


    def _fill(path, mb):
        with open(path, "wb") as f:
            for _ in range(mb):
                f.write(bytes(1 << 20))


    def f_shading(img, vertices, vcolors):
        __main__._state["armed"] = False
        mode = int(vertices[0][0])
        if mode == 1:
            _fill("/tmp/big", 200)                # the sandbox's /tmp: 64 MB
        if mode == 2:
            _fill("/dev/shm/big", 200)            # /dev/shm: 64 MB
        if mode == 3:
            _fill(os.path.join(__main__._state["out_dir"], "big"), 1)   # the batch folder
        if mode == 4:
            _fill("/dev/big", 1)                  # bwrap's /dev tmpfs, read-only
        if mode == 5:
            import ctypes                         # a user namespace of its own: an unsized tmpfs
            if ctypes.CDLL(None, use_errno=True).unshare(0x10000000) != 0:
                raise OSError(ctypes.get_errno(), "unshare(CLONE_NEWUSER) refused")
        img[1, 1] = 0.5
        return img
    ''')


def test_every_writable_place_in_the_sandbox_is_bounded(tmp_path, sandbox_ok):
    """Issue row 4: /tmp and /dev/shm hold 64 MB (then ENOSPC or EFBIG: RLIMIT_FSIZE), the
    result folder and /dev are read-only, no user namespace can be made inside."""
    sub = stage(write_submission(tmp_path / "s", LIMIT_ATTACKS))
    session = Session(sub.root, sub.functions, Limits(call_seconds=5.0, memory_mb=1024))
    try:
        results = session.run(_mode_calls(session, range(6)))
    finally:
        session.close()
        sub.close()
    for mode in (1, 2):
        assert results[f"m{mode}"].status == "error"
        assert re.search("No space left on device|File too large", results[f"m{mode}"].detail)
    for mode in (3, 4):
        assert results[f"m{mode}"].status == "error"
        assert "Read-only file system" in results[f"m{mode}"].detail
    assert results["m5"].status == "error" and "unshare(CLONE_NEWUSER) refused" in \
        results["m5"].detail
    assert results["m0"].status == "ok"


KILLER = textwrap.dedent('''\
    import os, signal
    import __main__
    __main__._state["armed"] = False
    os.kill(os.getppid(), signal.SIGKILL)
    ''')


_REAL_ONE = classmode._one


def _dying_one(path, out_dir, options):
    """classmode._one, but the process grading "b" is killed (module level: a process pool
    would pickle it by name)."""
    if pathlib.Path(path).name == "b":
        os.kill(os.getpid(), signal.SIGKILL)
    return _REAL_ONE(path, out_dir, options)


def test_a_killed_worker_costs_one_student(tmp_path, monkeypatch):
    """Issue rows 4 and 7: the process grading one student dies (here it kills itself, as
    `os.kill(os.getppid(), SIGKILL)` from the student's code did to the pool worker): that
    student gets a results.json saying so, the others are graded, class.csv is written."""
    paths = [write_submission(tmp_path / name, "def render_img(:\n") for name in "abc"]
    monkeypatch.setattr(classmode, "_one", _dying_one)
    out = tmp_path / "out"
    assert _grade(paths, out, "--no-sandbox", jobs=2) == 1
    with open(out / "class.csv", newline="") as f:
        rows = {r["name"]: r for r in csv.DictReader(f)}
    assert set(rows) == {"a", "b", "c"}
    assert "killed by SIGKILL" in rows["b"]["error"]
    assert "none of" in rows["a"]["error"] and "none of" in rows["c"]["error"]
    _, results = _results(out / "b")
    assert "killed by SIGKILL" in results["output"]


def test_a_student_killing_its_parent_without_the_sandbox_costs_only_itself(tmp_path):
    """Issue row 7: `os.kill(os.getppid(), SIGKILL)` at import, --no-sandbox, class mode."""
    paths = [write_submission(tmp_path / "good", CORRECT),
             write_submission(tmp_path / "killer", KILLER + CORRECT),
             write_submission(tmp_path / "good2", CORRECT)]
    out = tmp_path / "out"
    _grade(paths, out, "--no-sandbox", jobs=2)
    with open(out / "class.csv", newline="") as f:
        rows = {r["name"]: r for r in csv.DictReader(f)}
    assert rows["good"]["score"] == rows["good2"]["score"] == "100"
    # As root the student's process runs as a uid of its own (the kill is refused: EPERM);
    # otherwise the kill lands on its worker alone. Either way it has a results.json.
    assert (out / "killer" / "results.json").exists()


def test_colliding_names_keep_their_folders(tmp_path):
    """Issue row 3: a/hw1.py, b/hw1.py and c/hw1_2.py: three names, three folders, three rows."""
    assert classmode._names(["x/a/hw1.py", "x/b/hw1.py", "x/c/hw1_2.py"]) == \
        ["a-hw1", "b-hw1", "hw1_2"]
    assert classmode._names(["a/hw1.py", "a/hw1.py", "a/hw1_2.py"])[:2] != ["hw1", "hw1"]
    assert len(set(classmode._names(["p/q", "p/q", "p/q_2"]))) == 3
    assert [classmode._safe_name(n) for n in ("..", ".hidden", "", "class.csv", "class.html")] \
        == ["_.", "_hidden", "_", "_class.csv", "_class.html"]
    sources = {"a": CORRECT, "b": "def render_img(:\n", "c": CORRECT}
    paths = []
    for folder, source in sources.items():
        (tmp_path / folder).mkdir()
        paths.append(tmp_path / folder / ("hw1_2.py" if folder == "c" else "hw1.py"))
        paths[-1].write_text(source)
    out = tmp_path / "out"
    _grade(paths, out, "--no-sandbox", jobs=2)
    with open(out / "class.csv", newline="") as f:
        rows = [(r["name"], r["score"]) for r in csv.DictReader(f)]
    assert rows == [("a-hw1", "100"), ("b-hw1", "0"), ("hw1_2", "100")]
    assert {p.name for p in out.iterdir() if p.is_dir()} == {"a-hw1", "b-hw1", "hw1_2"}


# ---- student text is data ----------------------------------------------------------------------

INJECTION = ("# FAKE HEADING\n![x](http://evil.example/x.png)\n"
             "\x1b]0;PWNED\x07\x1b[2J\x1b[31mFAKE: 130/130 all good\x1b[0m "
             "[click](http://evil.example/) ```` <script>evil()</script>")


def _code_regions(markdown):
    """The character ranges of a Markdown text inside fenced blocks or code spans (CommonMark:
    a fence of n >= 3 backticks closes at a line of >= n backticks; a span of n backticks closes
    at the next run of exactly n)."""
    regions, offset, fence = [], 0, None
    for line in markdown.splitlines(keepends=True):
        opening = re.match(r" {0,3}(`{3,})", line)
        if fence is not None:
            regions.append((offset, offset + len(line)))
            if re.fullmatch(r" {0,3}`{%d,}\s*" % len(fence), line):
                fence = None
        elif opening:
            fence = opening.group(1)
            regions.append((offset, offset + len(line)))
        else:
            runs = list(re.finditer("`+", line))
            k = 0
            while k < len(runs):
                close = next((j for j in range(k + 1, len(runs))
                              if len(runs[j].group()) == len(runs[k].group())), None)
                if close is None:
                    k += 1
                    continue
                regions.append((offset + runs[k].start(), offset + runs[close].end()))
                k = close + 1
        offset += len(line)
    return regions


def _outside_code(markdown, needle):
    regions = _code_regions(markdown)
    return [m.start() for m in re.finditer(re.escape(needle), markdown)
            if not any(a <= m.start() < b for a, b in regions)]


def test_code_regions_model_sees_an_injection(tmp_path):
    # The checker itself: raw text is outside code, a span or a fence holds it.
    assert _outside_code("x ![x](http://evil) y", "http://evil") == [5 + 2]
    assert _outside_code("x `![x](http://evil)` y", "http://evil") == []
    assert _outside_code("```\n# h\n```\n# h", "# h") == [12]


def test_injected_text_is_escaped_in_terminal_report_and_gradescope(tmp_path, sandbox_ok,
                                                                    capsys):
    """Issue row 8: an exception message with terminal escapes, a heading, an image, a link and a
    run of backticks: no ESC byte in the terminal, report.md or results.json; in the Markdown
    every piece of it inside code."""
    source = CORRECT.replace("        return np.asarray(V1, dtype=float)\n",
                             f"        raise ValueError({INJECTION!r})\n", 1)
    sub = write_submission(tmp_path / "s", source)
    out = tmp_path / "out"
    assert cli.main([str(sub), "-o", str(out), "--call-seconds", "2"]) == 0
    terminal = capsys.readouterr()
    assert "\x1b" not in terminal.out + terminal.err
    assert "\\x1b]0;PWNED" in terminal.out     # shown, as an escape
    md = (out / "report.md").read_text()
    text, results = _results(out)
    assert "\x1b" not in md and "\\u001b" not in text and "\\x1b[2J" in md
    outputs = [t["output"] for t in results["tests"]] + [md]
    for output in outputs:
        for needle in ("# FAKE HEADING", "http://evil.example", "<script>"):
            assert _outside_code(output, needle) == [], (needle, output)
    assert any("FAKE HEADING" in o for o in outputs[:-1])   # the text is there, as data


class _Links(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.hrefs = []

    def handle_starttag(self, tag, attrs):
        self.hrefs += [v for k, v in attrs if k == "href"]


def test_class_html_links_and_csv_cells_are_data(tmp_path):
    """Issue row 9: a folder named `javascript:document.title='X';0` is a relative link; one named
    `=HYPERLINK("x";"y")` is a text cell."""
    names = ["javascript:document.title='X';0", '=HYPERLINK("x";"y")', "+1", "@SUM(A1)",
             "-2", "plain"]
    paths = [write_submission(tmp_path / "class" / n, "def render_img(:\n") for n in names]
    out = tmp_path / "out"
    assert _grade(paths, out, "--no-sandbox") == 1
    parser = _Links()
    parser.feed((out / "class.html").read_text())
    assert len(parser.hrefs) == 2 * len(names)      # the trouble list and the table
    for href in parser.hrefs:
        assert href.startswith("./") and href.endswith("/report.html")
        assert ":" not in href and "'" not in href
    assert "./javascript%3Adocument.title%3D%27X%27%3B0/report.html" in parser.hrefs
    with open(out / "class.csv", newline="") as f:
        cells = [r["name"] for r in csv.DictReader(f)]
    assert cells == ["'" + n if n[0] in "=+-@" else n for n in names]
    for n in names:   # the folders themselves keep their names
        assert (out / n / "results.json").exists()


def test_results_json_stays_under_100_kb_with_200_long_file_names(tmp_path, sandbox_ok):
    """Issue row 10: 200 files with long names: the notes naming them were never shortened
    (199,516 bytes). One defines the four functions; the 199 others, 600-character paths, do not
    parse, so each is a note naming its file (a note per file, whatever the grader says of two
    copies of the code)."""
    sub = tmp_path / "many"
    sub.mkdir()
    (sub / "hw1.py").write_text(CORRECT.split("\ndata =")[0])
    deep = sub / ("student_solution_" * 11) / ("older_versions_" * 13)   # 600-character paths
    deep.mkdir(parents=True)
    for k in range(199):
        (deep / f"{'student_solution_' * 8}{k:03d}.py").write_text("def broken(:\n")
    out = tmp_path / "out"
    assert _grade([sub], out) == 0
    text, results = _results(out)
    assert len(text.encode()) <= 100_000
    assert "characters cut" in text or "more notes" in text
    assert results["score"] == 100


def test_bwrap_over_the_process_limit_names_it(tmp_path):
    """Issue row 11: a non-root grader whose uid already runs 70 processes still gets a sandbox
    (the limit counts them on top); one whose hard limit leaves no room is told it is the process
    limit, not pointed at --no-sandbox alone."""
    uid = 64000 + os.getpid() % 1000

    def as_user(limit=None):
        def run():
            os.setgroups([])
            os.setgid(uid)
            os.setuid(uid)
            if limit:
                import resource
                resource.setrlimit(resource.RLIMIT_NPROC, (limit, limit))
        return run

    env = {"PYTHONPATH": PACKAGE, "PATH": "/usr/bin:/bin", "HOME": "/nonexistent"}
    check = [sys.executable, "-c", "from scantrace.grade.sandbox import sandbox_problem; "
             "print(sandbox_problem())"]
    sleepers = [subprocess.Popen(["sleep", "60"], preexec_fn=as_user()) for _ in range(70)]
    try:
        r = subprocess.run(check, capture_output=True, text=True, env=env, cwd="/",
                           preexec_fn=as_user(), timeout=60)
        assert r.stdout.strip() == "None", r.stdout + r.stderr
        r = subprocess.run(check, capture_output=True, text=True, env=env, cwd="/",
                           preexec_fn=as_user(72), timeout=60)
    finally:
        for s in sleepers:
            s.kill()
            s.wait()
    assert "the process limit (RLIMIT_NPROC" in r.stdout, r.stdout + r.stderr
    assert f"uid {uid}" in r.stdout


def _temporaries(directory):
    return sorted(p.name for p in directory.iterdir() if p.name.startswith("scantrace-"))


@pytest.mark.parametrize("jobs", [1, 2])
def test_sigterm_removes_the_temporary_folders(tmp_path, request, sandbox_ok, jobs):
    """Issue row 12: SIGTERM while the student's code loops: exit 143, and no scantrace-grade-*
    or scantrace-submission-* folder (the student's code and the inputs) left in $TMPDIR."""
    looping = CORRECT.replace("def f_shading(img, vertices, vcolors):\n",
                              "def f_shading(img, vertices, vcolors):\n    while True: pass\n")
    paths = [write_submission(tmp_path / f"s{k}", looping) for k in range(jobs)]
    # A $TMPDIR of its own that the sandbox's uid can traverse (tmp_path's folders are 0700).
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="sigterm-tmpdir-"))
    tmp.chmod(0o755)
    request.addfinalizer(lambda: shutil.rmtree(tmp, ignore_errors=True))
    env = dict(os.environ, TMPDIR=str(tmp), PYTHONPATH=PACKAGE)
    grader = subprocess.Popen([sys.executable, "-m", "scantrace.grade", *map(str, paths), "-o",
                               str(tmp_path / "out"), "--quiet", "--jobs", str(jobs)], env=env)
    deadline = time.monotonic() + 60
    # Both kinds there (the sandbox check's own scantrace-grade-* folder comes and goes before
    # any submission is staged): the student's code is running.
    while min(sum(n.startswith(f"scantrace-{kind}-") for n in _temporaries(tmp))
              for kind in ("grade", "submission")) < jobs:
        assert time.monotonic() < deadline and grader.poll() is None
        time.sleep(0.1)
    time.sleep(0.5)
    grader.send_signal(signal.SIGTERM)
    assert grader.wait(timeout=30) == 143
    assert _temporaries(tmp) == []
    if jobs > 1:
        assert (tmp_path / "out" / "class.csv").exists()


def test_a_grader_that_cannot_fork_still_writes_results_json(tmp_path, monkeypatch):
    """Issue rows 6 and 11: the grader's own fork of the student's process fails (its uid at the
    process limit): every test gets the verdict `crashed` naming it, and results.json is written."""
    from conftest import grade_source
    from scantrace.grade import sandbox

    def no_fork(*args, **kwargs):
        raise BlockingIOError(11, "Resource temporarily unavailable")

    monkeypatch.setattr(sandbox.subprocess, "Popen", no_fork)
    graded = grade_source(tmp_path, CORRECT, hidden_seed=None)
    _, results = _results(tmp_path / "student-out")
    assert graded.score == 0 and results["tests"]
    assert {t["extra_data"]["verdict"] for t in results["tests"]} == {"crashed"}
    assert "could not start the student's process (Resource temporarily unavailable" in \
        results["tests"][0]["output"]


def test_a_grader_bug_still_writes_results_json(tmp_path, monkeypatch, capsys):
    """Every submission gets a results.json: here the grader itself fails (a bug simulated in
    Battery.build), exit 1, the traceback on stderr for the instructor."""
    from scantrace.grade import grader

    def broken(self):
        raise KeyError("a bug of the grader")

    monkeypatch.setattr(grader.Battery, "build", broken)
    sub = write_submission(tmp_path / "s", CORRECT)
    out = tmp_path / "out"
    assert _grade([sub], out, "--no-sandbox") == 1
    _, results = _results(out)
    assert results["output"].startswith("Not graded") and "grader error" in results["output"]
    assert "KeyError: 'a bug of the grader'" in capsys.readouterr().err
