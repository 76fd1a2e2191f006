"""Runs a batch of calls to a student's functions in a child process under bubblewrap.

The child sees a read-only system (/usr and the few /etc files the dynamic linker needs), the
submission read-only at /submission, the harness at /harness, the grader's inputs read-only at
/out, and a private /tmp and /dev/shm of Limits.tmp_mb each; nothing else of the machine (not the
grader's files, the hidden seed, the rubric or other submissions), no network, no other process,
no further user namespace. When the grader runs as root the child runs as an unprivileged uid.
Limits: CPU time, address space and file size (rlimits), processes (RLIMIT_NPROC, on a uid of its
own per grading process), wall time per call (an alarm in the harness) and per batch (the grader
kills the process group), output (the grader counts the bytes of the pipe), results (the channel,
channel.py).

What comes back is data, through a pipe: length-prefixed records checked in order and size
(channel.py), never a file the child could have replaced, never a pickle.
"""

import dataclasses
import functools
import json
import os
import pathlib
import resource
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import numpy as np

from . import channel, untrusted

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
    tmp_mb: int = 64                  # the child's /tmp and /dev/shm (each), and any one file
    results_mb: int = 256             # the values sent back by all the children of a submission


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


@functools.lru_cache(maxsize=1)
def _bwrap_can(option):
    try:
        return option in subprocess.run(["bwrap", "--help"], capture_output=True, text=True,
                                         timeout=10).stdout
    except (OSError, subprocess.SubprocessError):
        return False


def _bwrap_command(work, submission, python_args, tmp_mb=64):
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
    # No nested user namespace: inside one the student could mount a tmpfs of no size limit.
    userns = ["--unshare-user", "--disable-userns"] if _bwrap_can("--disable-userns") else []
    # bubblewrap < 0.5 has no --size: its tmpfs are then bounded by RLIMIT_FSIZE per file only.
    size = ["--size", str(tmp_mb * 1024 * 1024)] if _bwrap_can("--size") else []
    # /dev is bwrap's own tmpfs, of no size limit: read-only, with a sized /dev/shm in it.
    return ["bwrap", "--unshare-all", *userns, "--die-with-parent", "--new-session",
            "--ro-bind", "/usr", "/usr", *links, *etc,
            "--proc", "/proc", "--dev", "/dev", *size, "--tmpfs", "/dev/shm",
            "--remount-ro", "/dev", *size, "--tmpfs", "/tmp",
            "--ro-bind", str(submission), "/submission",
            "--ro-bind", str(HARNESS.resolve()), "/harness/harness.py",
            "--ro-bind", str(work), "/out", "--chdir", "/tmp", *uid,
            "--clearenv", "--setenv", "HOME", "/tmp", "--setenv", "TMPDIR", "/tmp",
            "--setenv", "PATH", "/usr/bin:/bin", "--setenv", "LANG", "C.UTF-8",
            "--setenv", "MPLBACKEND", "Agg", "--setenv", "OPENBLAS_NUM_THREADS", "1",
            "--setenv", "OMP_NUM_THREADS", "1", "--setenv", "PYTHONDONTWRITEBYTECODE", "1",
            PYTHON, *python_args]


def _tasks_of(uid):
    """Processes and threads the uid runs now: what RLIMIT_NPROC counts against it."""
    count = 0
    for pid in os.listdir("/proc"):
        try:
            with open(f"/proc/{pid}/status", "rb") as f:
                fields = dict(line.split(b":", 1) for line in f.read(4096).splitlines()
                              if b":" in line)
            if int(fields[b"Uid"].split()[0]) == uid:
                count += int(fields[b"Threads"])
        except (OSError, KeyError, ValueError, IndexError):
            continue
    return count


def _process_limit(limits, drop_to):
    """RLIMIT_NPROC counts every process of the uid: a non-root grader's own count comes on top
    of the sandbox's allowance (its user may already run 64 processes), within the hard limit."""
    if drop_to is not None or os.geteuid() == 0:
        return limits.processes
    wanted = _tasks_of(os.getuid()) + limits.processes
    hard = resource.getrlimit(resource.RLIMIT_NPROC)[1]
    return wanted if hard == resource.RLIM_INFINITY else min(wanted, hard)


def _preexec(limits, drop_to):
    nproc = _process_limit(limits, drop_to)

    def run():
        resource.setrlimit(resource.RLIMIT_CPU, (limits.cpu_seconds, limits.cpu_seconds + 5))
        memory = limits.memory_mb * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        size = limits.tmp_mb * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_FSIZE, (size, size))
        if drop_to is not None:
            os.setgroups([])
            os.setgid(drop_to)
            os.setuid(drop_to)
        resource.setrlimit(resource.RLIMIT_NPROC, (nproc, nproc))
    return run


def _cause(stderr, limits, drop_to):
    """bwrap's failure in words that name its cause and what to change."""
    text = untrusted.one_line(stderr.strip())[:300]
    if "Resource temporarily unavailable" in stderr or "Cannot allocate memory" in stderr:
        uid = os.getuid()
        return (f"bwrap could not start a process: the process limit (RLIMIT_NPROC, `ulimit -u`) "
                f"is reached for uid {uid}, which runs {_tasks_of(uid)} processes and threads "
                f"against a limit of {_process_limit(limits, drop_to)}; raise `ulimit -u` or "
                f"stop some of them ({text})")
    if "namespace" in stderr.lower() or "Operation not permitted" in stderr:
        return ("bwrap cannot create the sandbox's namespaces here (unprivileged user namespaces "
                "are disabled: sysctl kernel.unprivileged_userns_clone or "
                f"user.max_user_namespaces, or a container that forbids them): {text}")
    return f"bwrap cannot create the sandbox here: {text}"


def sandbox_problem(limits=None):
    """None when bwrap can create the sandbox here; else one line saying why not."""
    if shutil.which("bwrap") is None:
        return "bwrap (Debian's bubblewrap) is not installed"
    limits = limits or Limits()
    with tempfile.TemporaryDirectory(prefix="scantrace-grade-") as d:
        command = _bwrap_command(d, d, ["-c", "pass"], limits.tmp_mb)
        drop = _sandbox_uid() if os.geteuid() == 0 else None
        if drop is not None:
            os.chmod(d, 0o755)
        try:
            r = subprocess.run(command, capture_output=True, text=True,
                               preexec_fn=_preexec(limits, drop), timeout=30)
        except (OSError, subprocess.SubprocessError) as e:
            return _cause(str(e), limits, drop)
    return _cause(r.stderr, limits, drop) if r.returncode != 0 else None


class _Output:
    """The child's stdout+stderr: counted (a submission printing 100 MB must not fill the
    grader's memory or disk), the last 4 KB kept for the report."""

    def __init__(self, limit):
        self.limit = limit
        self.total, self.tail, self.over = 0, b"", False

    def feed(self, chunk):
        self.total += len(chunk)
        self.tail = (self.tail + chunk)[-4096:]
        self.over = self.over or self.total > self.limit

    def last_lines(self, n=10):
        text = untrusted.clean(self.tail.decode("utf-8", "replace"))
        return "\n".join(text.rstrip().splitlines()[-n:])


def _kill(process):
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def _watch(process, result_fd, reader, output, seconds):
    """Reads the child's output and result pipes until both close, the child has exited for a
    second (a grandchild may keep a pipe open), the time is up or either stream breaks its
    budget. True when the time ran out."""
    streams = {process.stdout.fileno(): output.feed, result_fd: reader.feed}
    deadline = time.monotonic() + seconds
    exited = None
    while streams:
        now = time.monotonic()
        if now >= deadline:
            return True
        if process.poll() is not None:
            exited = exited or now
            if now - exited > 1.0:
                return False
        ready, _, _ = select.select(list(streams), [], [], min(0.2, deadline - now))
        for fd in ready:
            data = os.read(fd, 65536)
            if data:
                streams[fd](data)
            else:
                del streams[fd]
        if output.over or reader.broken:
            _kill(process)
            return False
    try:
        process.wait(timeout=max(deadline - time.monotonic(), 0.01))
    except subprocess.TimeoutExpired:
        return True
    return False


class Session:
    """The calls of one submission: inputs written once, children started until every call has a
    result (a child that dies takes only the call it was running with it)."""

    def __init__(self, submission, functions, limits, sandbox=True):
        self.submission, self.functions = pathlib.Path(submission), functions
        self.limits, self.sandbox = limits, sandbox
        self.work = pathlib.Path(tempfile.mkdtemp(prefix="scantrace-grade-"))
        (self.work / "in").mkdir()
        (self.work / "in").chmod(0o755)   # readable by the child's uid whatever the umask
        self.inputs = 0
        self.spent = 0.0
        self.results_left = limits.results_mb * 1024 * 1024
        self.import_status = None
        self.skipped_demo = []

    def close(self):
        shutil.rmtree(self.work, ignore_errors=True)

    def input(self, array):
        """Writes an input array (.npy without pickles); returns the name calls refer to it by."""
        self.inputs += 1
        name = f"in/{self.inputs}.npy"
        np.save(self.work / name, np.ascontiguousarray(array), allow_pickle=False)
        (self.work / name).chmod(0o644)
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
            self._child(pending, results)
            if self.import_status is not None and self.import_status.status != "ok":
                for call in pending:
                    results.setdefault(call["id"], CallResult(
                        self.import_status.status, self.import_status.detail))
                break
            pending = [c for c in pending if c["id"] not in results]
        return results

    def _module_paths(self):
        """Modules whose file name has a dot besides .py (hw1.final.py): the harness loads them
        by path, since `import hw1.final` would look for a package hw1."""
        # A function's module is "module" or "module:name" (another year's name).
        wanted, paths = {str(m).partition(":")[0] for m in self.functions.values()}, {}
        for path in sorted(self.submission.rglob("*.py")):
            rel = path.relative_to(self.submission)
            module = ".".join(rel.with_suffix("").parts)
            if "." in rel.stem and module in wanted and not path.is_symlink():
                paths[module] = str(rel)
        return paths

    def _spec(self, calls, batch_out, result_fd):
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
                     "write_roots": ["/dev/null"]}
            paths = {"submission": str(self.submission), "out": str(batch_out)}
            harness = str(HARNESS)
        # Inputs are referred to relative to the batch folder: the batch sees them through ../in.
        calls = [{"timeout": self.limits.call_seconds, "max_values": channel.max_values(c),
                  **_relative_inputs(c)} for c in calls]
        spec = {**paths, **roots, "functions": self.functions, "calls": calls,
                "module_paths": self._module_paths(), "result_fd": result_fd,
                "import_timeout": self.limits.call_seconds}
        (batch_out / "spec.json").write_text(json.dumps(spec))
        (batch_out / "spec.json").chmod(0o644)
        return harness, paths["out"] + "/spec.json"

    def _command(self, harness, spec):
        args = ["-I", "-B", harness, spec]   # -B: no .pyc written into the submission
        if self.sandbox:
            return _bwrap_command(self.work, self.submission, args, self.limits.tmp_mb), None
        return [PYTHON, *args], {"PATH": "/usr/bin:/bin", "HOME": "/nonexistent",
                                 "MPLBACKEND": "Agg", "OPENBLAS_NUM_THREADS": "1",
                                 "PYTHONDONTWRITEBYTECODE": "1"}

    def _child(self, calls, results):
        # The batch folder is the grader's and read-only to the child (spec.json): results come
        # back through the pipe alone, so the child has no file of the grader to plant or fill.
        batch_out = pathlib.Path(tempfile.mkdtemp(dir=self.work, prefix="batch-"))
        batch_out.chmod(0o755)
        os.chmod(self.work, 0o755)
        # Without the sandbox a root grader still drops the child to a uid of its own.
        drop = _sandbox_uid() if os.geteuid() == 0 else None
        read_fd, write_fd = os.pipe()
        try:
            command, env = self._command(*self._spec(calls, batch_out, write_fd))
            start = time.monotonic()
            process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                       stdin=subprocess.DEVNULL, start_new_session=True, env=env,
                                       cwd=batch_out, pass_fds=(write_fd,),
                                       preexec_fn=_preexec(self.limits, drop))
        except OSError as e:
            # The grader's own fork failed (its uid at the process limit, no memory): every call
            # left gets a verdict saying so, and the report is still written.
            os.close(read_fd)
            self.import_status = CallResult("crashed", "the grader could not start the "
                                            f"student's process ({e.strerror}: the process "
                                            "limit, or memory)")
            return False
        except BaseException:
            os.close(read_fd)
            raise
        finally:
            os.close(write_fd)
        reader = channel.Reader(calls, self.results_left)
        output = _Output(self.limits.output_bytes)
        budget = min(self.limits.batch_seconds, self.limits.submission_seconds - self.spent)
        try:
            timed_out = _watch(process, read_fd, reader, output, max(budget, 1.0))
        finally:
            _kill(process)
            process.wait()
            process.stdout.close()
            os.close(read_fd)
        self.spent += time.monotonic() - start
        self.results_left -= reader.payload_bytes
        return self._collect(calls, results, reader, process.returncode, timed_out, output)

    def _collect(self, calls, results, reader, returncode, timed_out, output):
        started, ended = reader.started, reader.ended
        ids = {c["id"] for c in calls}
        for call_id, record in ended.items():
            if call_id == "import":
                self.import_status = CallResult(record["status"], record["detail"])
                self.skipped_demo = record["skipped"]
            elif call_id in ids and call_id not in results:
                results[call_id] = CallResult(record["status"], record["detail"],
                                              record["value"], record["returned"])
        if reader.broken:
            verdict = CallResult("forbidden", "its process wrote into the grader's result channel "
                                 f"what the harness never writes: {reader.broken}")
            if reader.current() == "import":
                self.import_status = verdict
            elif reader.current() in ids:
                results.setdefault(reader.current(), verdict)
            return False
        running = [c for c in started if c not in ended]
        if running:
            verdict = self._death(returncode, timed_out, output)
            if running[-1] == "import":
                self.import_status = verdict
            else:
                results[running[-1]] = verdict
            return False
        if not started:
            self.import_status = self._death(returncode, timed_out, output)
        elif not reader.finished and reader.current() in ids:
            # Between two calls: the next call is the one the death stops.
            results.setdefault(reader.current(), self._death(returncode, timed_out, output))
        return True

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
