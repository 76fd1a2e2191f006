"""Runs a batch of calls to a student's functions in a child process under bubblewrap.

The child sees a read-only system (/usr and the few /etc files the dynamic linker needs), the
submission read-only at /submission, the harness at /harness, a private /tmp and its result
folder at /out; nothing else of the machine (not the grader's files, the hidden seed, the rubric
or other submissions), no network, no other process. When the grader runs as root the child runs
as an unprivileged uid. Limits: CPU time and address space (rlimits), processes (RLIMIT_NPROC, on
a uid of its own per grading process), wall time per call (an alarm in the harness) and per batch
(the grader kills the process group), output (the grader counts the bytes of the pipe).

What comes back is data: a JSON-lines status file and raw float64 buffers whose size the grader
checks against the shape declared, never a pickle.
"""

import dataclasses
import json
import os
import pathlib
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np

HARNESS = pathlib.Path(__file__).with_name("harness.py")
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable


@dataclasses.dataclass
class Limits:
    call_seconds: float = 10.0        # wall time of one call
    batch_seconds: float = 120.0      # wall time of one child (all its calls)
    submission_seconds: float = 300.0 # wall time of all the children of one submission
    cpu_seconds: int = 120            # CPU time of one child
    memory_mb: int = 2048             # address space of one child
    processes: int = 64               # processes and threads of the sandbox's uid
    output_bytes: int = 1_000_000     # stdout + stderr of one child


@dataclasses.dataclass
class CallResult:
    status: str                        # ok, error, timeout, memory, forbidden, crashed, not_run
    detail: str = ""
    value: np.ndarray | None = None
    returned: str = ""                 # the Python type the student returned (ndarray, list…)


class SandboxUnavailable(RuntimeError):
    pass


def _sandbox_uid():
    # A uid of its own per grading process: RLIMIT_NPROC counts per uid, so a fork bomb in one
    # submission cannot starve the sandboxes of the other --jobs workers.
    return 61000 + os.getpid() % 4000


def _bwrap_command(work, submission, python_args):
    etc = [a for f in ("/etc/alternatives", "/etc/ld.so.cache", "/etc/ld.so.conf",
                       "/etc/ld.so.conf.d") if os.path.exists(f) for a in ("--ro-bind", f, f)]
    links = []
    for name in ("lib", "lib64", "bin", "lib32"):
        target = os.path.join("/", name)
        if os.path.islink(target):
            links += ["--symlink", os.readlink(target), target]
        elif os.path.isdir(target):
            links += ["--ro-bind", target, target]
    uid = ["--uid", str(os.getuid()), "--gid", str(os.getgid())]
    return ["bwrap", "--unshare-all", "--die-with-parent", "--new-session",
            "--ro-bind", "/usr", "/usr", *links, *etc,
            "--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp",
            "--ro-bind", str(submission), "/submission",
            "--ro-bind", str(HARNESS.resolve()), "/harness/harness.py",
            "--bind", str(work), "/out", "--chdir", "/tmp", *uid,
            "--clearenv", "--setenv", "HOME", "/tmp", "--setenv", "TMPDIR", "/tmp",
            "--setenv", "PATH", "/usr/bin:/bin", "--setenv", "LANG", "C.UTF-8",
            "--setenv", "MPLBACKEND", "Agg", "--setenv", "OPENBLAS_NUM_THREADS", "1",
            "--setenv", "OMP_NUM_THREADS", "1", "--setenv", "PYTHONDONTWRITEBYTECODE", "1",
            PYTHON, *python_args]


def _preexec(limits, drop_to):
    def run():
        resource.setrlimit(resource.RLIMIT_CPU, (limits.cpu_seconds, limits.cpu_seconds + 5))
        memory = limits.memory_mb * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        if drop_to is not None:
            os.setgroups([])
            os.setgid(drop_to)
            os.setuid(drop_to)
        resource.setrlimit(resource.RLIMIT_NPROC, (limits.processes, limits.processes))
    return run


def sandbox_problem():
    """None when bwrap can create the sandbox here; else one line saying why not."""
    if shutil.which("bwrap") is None:
        return "bwrap (Debian's bubblewrap) is not installed"
    with tempfile.TemporaryDirectory() as d:
        command = _bwrap_command(d, d, ["-c", "pass"])
        drop = _sandbox_uid() if os.geteuid() == 0 else None
        if drop is not None:
            os.chmod(d, 0o777)
        r = subprocess.run(command, capture_output=True, text=True,
                           preexec_fn=_preexec(Limits(), drop), timeout=30)
    if r.returncode != 0:
        return f"bwrap cannot create the sandbox's namespaces here: {r.stderr.strip()[:300]}"
    return None


class _Output(threading.Thread):
    """Reads the child's stdout+stderr, keeps the last 4 KB, and kills the child when the total
    passes the limit (a submission printing 100 MB must not fill the grader's memory or disk)."""

    def __init__(self, process, limit):
        super().__init__(daemon=True)
        self.process, self.limit = process, limit
        self.total, self.tail, self.over = 0, b"", False

    def run(self):
        while True:
            chunk = self.process.stdout.read(65536)
            if not chunk:
                return
            self.total += len(chunk)
            self.tail = (self.tail + chunk)[-4096:]
            if self.total > self.limit and not self.over:
                self.over = True
                _kill(self.process)

    def last_lines(self, n=10):
        text = self.tail.decode("utf-8", "replace")
        return "\n".join(text.rstrip().splitlines()[-n:])


def _kill(process):
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def _read_status(path):
    started, ended = [], {}
    if not path.exists():
        return started, ended
    with open(path, "rb") as f:
        data = f.read(4_000_000)
    for line in data.decode("utf-8", "replace").splitlines():
        try:
            record = json.loads(line)
        except ValueError:
            continue
        if not isinstance(record, dict) or not isinstance(record.get("call"), str):
            continue
        if record.get("event") == "start":
            started.append(record["call"])
        elif record.get("event") == "end":
            ended[record["call"]] = record
    return started, ended


def _read_value(path, shape):
    """A raw float64 buffer, checked: its shape is small ints and its size exactly the shape's."""
    if not (isinstance(shape, list) and len(shape) <= 3
            and all(isinstance(n, int) and 0 <= n <= 8192 for n in shape)):
        raise ValueError(f"declared shape {shape!r} is not a small array shape")
    expected = 8 * int(np.prod(shape, dtype=np.int64))
    if not path.exists() or path.stat().st_size != expected:
        raise ValueError(f"{path.name}: expected {expected} bytes for shape {tuple(shape)}")
    return np.frombuffer(path.read_bytes(), dtype="<f8").reshape(shape).astype(np.float64)


class Session:
    """The calls of one submission: inputs written once, children started until every call has a
    result (a child that dies takes only the call it was running with it)."""

    def __init__(self, submission, functions, limits, sandbox=True):
        self.submission, self.functions = pathlib.Path(submission), functions
        self.limits, self.sandbox = limits, sandbox
        self.work = pathlib.Path(tempfile.mkdtemp(prefix="scantrace-grade-"))
        (self.work / "in").mkdir()
        self.inputs = 0
        self.spent = 0.0
        self.import_status = None
        self.skipped_demo = []

    def close(self):
        shutil.rmtree(self.work, ignore_errors=True)

    def input(self, array):
        """Writes an input array (.npy without pickles); returns the name calls refer to it by."""
        self.inputs += 1
        name = f"in/{self.inputs}.npy"
        np.save(self.work / name, np.ascontiguousarray(array), allow_pickle=False)
        return name

    def run(self, calls):
        results = {}
        pending = list(calls)
        while pending:
            if self.spent >= self.limits.submission_seconds:
                for call in pending:
                    results[call["id"]] = CallResult(
                        "timeout", "not run: the submission used up its total time limit")
                break
            done = self._child(pending, results)
            if self.import_status is not None and self.import_status.status != "ok":
                for call in pending:
                    results.setdefault(call["id"], CallResult(
                        self.import_status.status, self.import_status.detail))
                break
            pending = [c for c in pending if c["id"] not in results]
            if not done and pending:
                continue
        return results

    def _spec(self, calls, batch_out):
        if self.sandbox:
            roots = {}
            paths = {"submission": "/submission", "out": "/out/" + batch_out.name}
            harness = "/harness/harness.py"
        else:
            # The session's own folder, not the whole of /tmp: other sessions' submissions and
            # the grader's temporary files lie there too (a clone under /tmp let the student
            # read the grader's file planted by test_grade_sandbox).
            prefixes = sorted({sys.prefix, sys.base_prefix, "/usr", "/lib", "/etc", "/proc",
                               "/dev", "/sys", str(self.work)})
            roots = {"read_roots": [p.rstrip("/") + "/" for p in prefixes]
                     + [str(self.submission) + "/", str(HARNESS.parent) + "/"],
                     "write_roots": [str(self.work) + "/", "/dev/null"]}
            paths = {"submission": str(self.submission), "out": str(batch_out)}
            harness = str(HARNESS)
        # Inputs are referred to relative to the result folder: the batch sees them through ../in.
        calls = [{"timeout": self.limits.call_seconds, **_relative_inputs(c)} for c in calls]
        spec = {**paths, **roots, "functions": self.functions, "calls": calls,
                "import_timeout": self.limits.call_seconds}
        (batch_out / "spec.json").write_text(json.dumps(spec))
        return harness, paths["out"] + "/spec.json"

    def _child(self, calls, results):
        batch_out = pathlib.Path(tempfile.mkdtemp(dir=self.work, prefix="batch-"))
        harness, spec = self._spec(calls, batch_out)
        drop = _sandbox_uid() if (self.sandbox and os.geteuid() == 0) else None
        if drop is not None:
            os.chown(batch_out, drop, drop)
        os.chmod(self.work, 0o755)
        args = ["-I", "-B", harness, spec]   # -B: no .pyc written into the submission
        command = _bwrap_command(self.work, self.submission, args) if self.sandbox \
            else [PYTHON, *args]
        env = None if self.sandbox else {"PATH": "/usr/bin:/bin", "HOME": str(batch_out),
                                         "MPLBACKEND": "Agg", "OPENBLAS_NUM_THREADS": "1",
                                         "PYTHONDONTWRITEBYTECODE": "1"}
        start = time.monotonic()
        process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                   stdin=subprocess.DEVNULL, start_new_session=True, env=env,
                                   cwd=batch_out, preexec_fn=_preexec(self.limits, drop))
        output = _Output(process, self.limits.output_bytes)
        output.start()
        budget = min(self.limits.batch_seconds, self.limits.submission_seconds - self.spent)
        timed_out = False
        try:
            process.wait(timeout=max(budget, 1.0))
        except subprocess.TimeoutExpired:
            timed_out = True
            _kill(process)
            process.wait()
        output.join(timeout=5)
        self.spent += time.monotonic() - start
        return self._collect(calls, results, batch_out, process.returncode, timed_out, output)

    def _collect(self, calls, results, batch_out, returncode, timed_out, output):
        started, ended = _read_status(batch_out / "status.jsonl")
        for call_id, record in ended.items():
            if call_id == "import":
                self.import_status = CallResult(record.get("status", "crashed"),
                                                str(record.get("detail", "")))
                self.skipped_demo = [str(s) for s in record.get("skipped", [])][:20]
                continue
            if call_id in results or call_id not in {c["id"] for c in calls}:
                continue
            results[call_id] = self._result(record, batch_out, output)
        running = [c for c in started if c not in ended]
        if running:
            verdict = self._death(returncode, timed_out, output)
            if running[-1] == "import" or not started:
                self.import_status = verdict
            else:
                results[running[-1]] = verdict
            return False
        if not started:
            self.import_status = self._death(returncode, timed_out, output)
        return True

    def _result(self, record, batch_out, output):
        status = record.get("status")
        detail = str(record.get("detail", ""))[:4000]
        if status != "ok":
            if status not in ("error", "timeout", "memory", "forbidden", "crashed"):
                status, detail = "crashed", f"unreadable status {status!r}"
            return CallResult(status, detail)
        try:
            value = _read_value(batch_out / (record["call"] + ".bin"), record.get("shape"))
        except ValueError as e:
            return CallResult("crashed", f"its result could not be read back: {e}")
        return CallResult("ok", "", value, str(record.get("returned", ""))[:40])

    def _death(self, returncode, timed_out, output):
        tail = output.last_lines()
        tail = f"\n--- last lines of its output ---\n{tail}" if tail else ""
        if output.over:
            return CallResult("forbidden", f"printed more than {self.limits.output_bytes} bytes "
                              f"(the output limit){tail}")
        if timed_out:
            return CallResult("timeout", f"still running after {self.limits.batch_seconds:g} s "
                              f"(killed){tail}")
        if returncode == -signal.SIGXCPU:
            return CallResult("timeout", f"used its {self.limits.cpu_seconds} s of CPU{tail}")
        if returncode is not None and self.sandbox and returncode > 128:
            returncode = 128 - returncode   # bwrap exits 128 + n when its child dies of signal n
        if returncode is not None and returncode < 0:
            name = signal.Signals(-returncode).name
            return CallResult("crashed", f"the interpreter was killed by {name}{tail}")
        return CallResult("crashed", f"the interpreter exited with status {returncode} "
                          f"in the middle of the call (os._exit?){tail}")


def _relative_inputs(call):
    call = dict(call)
    for key in ("vertices", "faces", "vcolors", "order"):
        if key in call:
            call[key] = "../" + call[key]
    if "args" in call:
        call["args"] = [{"npy": "../" + a["npy"]} if isinstance(a, dict) else a
                        for a in call["args"]]
    return call
