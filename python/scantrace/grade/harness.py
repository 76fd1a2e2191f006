"""The child side of the grader: runs inside the sandbox, imports the student's modules and makes
the calls the grader asked for. Needs only numpy and the standard library (never scantrace).

    python3 -I harness.py SPEC.json

SPEC.json (written by the grader): {"submission": dir, "out": dir, "functions": {name: module},
"module_paths": {module: file}, "result_fd": n, "calls": [{"id", "kind": "call"|"faces",
"max_values", ...}]}. For every call the harness writes two records to the inherited pipe
`result_fd` (a "start" record, then an "end" record with the call's status): a 4-byte big-endian
length, a JSON object, and for an ok "end" the value returned as raw little-endian float64 bytes,
C order, its shape in the record (channel.py reads them, trusting nothing). Nothing returned is a
pickle, and the harness writes no file: the batch folder is read-only.
Statuses: ok, error (the student's exception), timeout, memory, forbidden (an operation the
sandbox does not allow, named). A call during which the process dies has a "start" and no "end":
the grader names that verdict (crashed, or timeout / output limit when it killed the child).
"""

import ast
import importlib
import importlib.machinery
import importlib.util
import json
import os
import signal
import sys
import traceback
import types

import numpy as np

# Where reads are allowed: the system (Python, numpy), the submission, the private temp dir and
# the harness itself. Everything else does not exist in the sandbox anyway; refusing it here turns
# a quiet FileNotFoundError into the verdict `forbidden` that names the path.
_READ_ROOTS = ("/usr/", "/lib", "/bin/", "/etc/", "/proc/", "/dev/", "/sys/", "/tmp/",
               "/submission/", "/harness/")
_WRITE_ROOTS = ("/tmp/", "/dev/null")
_FORBIDDEN_EVENTS = {
    "os.fork": "fork a process", "os.forkpty": "fork a process", "os.system": "run a shell",
    "os.exec": "run a program", "os.posix_spawn": "run a program", "os.spawn": "run a program",
    "subprocess.Popen": "run a program", "socket.__new__": "open a socket",
    "socket.connect": "connect a socket", "socket.bind": "bind a socket",
    "ctypes.dlopen": "load a C library with ctypes",
}


class Forbidden(BaseException):
    """Raised into the student's code when it tries what the sandbox forbids (a BaseException so
    that a bare ``except Exception`` in the submission does not swallow it)."""


class CallTimeout(BaseException):
    pass


_state = {"armed": False, "forbidden": None, "out_dir": None}


def _audit(event, args):
    if not _state["armed"]:
        return
    what = _FORBIDDEN_EVENTS.get(event)
    if what is None and event == "open":
        path, mode = args[0], args[1]
        if isinstance(path, int) or path is None:
            return
        path = os.path.abspath(os.fsdecode(path))
        writing = isinstance(mode, str) and any(c in mode for c in "wax+")
        if isinstance(mode, int) or mode is None:
            writing = bool(args[2] & (os.O_WRONLY | os.O_RDWR | os.O_CREAT)) if len(args) > 2 \
                and isinstance(args[2], int) else False
        roots = _WRITE_ROOTS if writing else _READ_ROOTS + (os.path.dirname(_state["out_dir"]) + "/",)
        if writing and path.startswith(_state["out_dir"] + "/"):
            what = "write into the grader's result folder"
        elif not (path + "/").startswith(roots) and not path.startswith(roots):
            what = f"{'write' if writing else 'read'} {path}"
    if what is not None:
        _state["forbidden"] = what
        raise Forbidden(what)


def _stub_module(name, **attributes):
    """A stand-in for a plotting or progress-bar package: every attribute is a no-op callable, so
    `plt.imshow(img); plt.show()` in a submission does nothing and waits for no window."""
    class _Anything:
        def __call__(self, *a, **k):
            return a[0] if len(a) == 1 and not k and hasattr(a[0], "__iter__") else _Anything()

        def __getattr__(self, _):
            return _Anything()

        def __iter__(self):
            return iter(())

        def __enter__(self):
            return self

        def __exit__(self, *a):
            return False

    class _Module(types.ModuleType):
        def __getattr__(self, _):
            return _Anything()

    module = _Module(name)
    module.__path__ = []
    for k, v in attributes.items():
        setattr(module, k, v)
    return module


def _tqdm(iterable=None, *a, **k):
    return iterable if iterable is not None else _stub_module("tqdm").x


def _install_stubs():
    # Always stubbed (even when installed): they draw windows, write caches or print bars.
    for name in ("matplotlib", "matplotlib.pyplot", "matplotlib.image", "matplotlib.animation",
                 "cv2", "PIL", "PIL.Image", "imageio", "IPython", "IPython.display"):
        sys.modules[name] = _stub_module(name)
    for name in ("tqdm", "tqdm.auto", "tqdm.notebook"):
        sys.modules[name] = _stub_module(name, tqdm=_tqdm, trange=lambda *a, **k: range(*a))
    sys.modules["matplotlib"].pyplot = sys.modules["matplotlib.pyplot"]


def _last_lines(text, n=8):
    return "\n".join(text.rstrip().splitlines()[-n:])


class _Status:
    """The result channel's writing end: length-prefixed JSON records, a value's bytes after."""

    def __init__(self, fd):
        self.fd = fd

    def write(self, payload=b"", **record):
        # The grader refuses a header over 64 KiB: a 10 MB exception message, or thousands of
        # skipped demo lines, must not turn an honest verdict into a broken channel.
        if "detail" in record:
            record["detail"] = str(record["detail"])[:4000]
        if "skipped" in record:
            record["skipped"] = [str(s)[:200] for s in record["skipped"][:20]]
        header = json.dumps(record).encode("utf-8")
        data = memoryview(len(header).to_bytes(4, "big") + header + payload)
        while data:
            data = data[os.write(self.fd, data):]


def _load(name):
    # Inputs are .npy files the grader wrote into the result folder, read without pickles.
    return np.load(os.path.join(_state["out_dir"], name), allow_pickle=False)


def _as_float_array(value, what):
    if isinstance(value, (int, float, np.integer, np.floating)):
        return np.asarray(float(value))
    try:
        array = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{what} returned a {type(value).__name__} that is not an array of "
                        f"numbers ({e})") from None
    return np.ascontiguousarray(array)


def _adapted(func, adapter):
    """The student's function of another year's API called with the course's arguments (the
    grader's signatures.adapter read its parameters): each parameter gets the course's argument
    of its role (reordered), the shading value is translated ('f' -> 'flat'), a fixed one is
    added (shade_triangle's 'flat' for f_shading), and a canvas parameter the course does not
    pass gets a blank canvas, returned when the function fills it in place."""
    if not adapter:
        return func

    def course_call(*args):
        given = dict(zip(adapter["course"], args))
        given.update(adapter["fixed"])
        if "shading" in given:
            given["shading"] = adapter["shading"].get(given["shading"], given["shading"])
        canvas = None
        if "img" in adapter["params"] and "img" not in given:
            canvas = given["img"] = np.ones(adapter["canvas"], dtype=np.float64)
        result = func(*[given[role] for role in adapter["params"]])
        return canvas if result is None and canvas is not None else result
    return course_call


def _run_call(call, functions, spec):
    func = functions.get(call["func"])
    if func is None:
        raise NameError(f"the submission's module has no function {call['func']}")
    func = _adapted(func, call.get("adapter"))
    if call["kind"] == "faces":
        # The scene drawn face by face through the student's shading function, in the order the
        # grader gives (the reference painter's order): the fill alone, without the student's sort.
        img = np.ones(call["canvas_shape"], dtype=np.float64)
        vertices, faces = _load(call["vertices"]), _load(call["faces"])
        vcolors = _load(call["vcolors"])
        for k in _load(call["order"]):
            face = faces[k]
            result = func(img, vertices[face], vcolors[face])
            if result is not None and result is not img:
                img = np.array(result, dtype=np.float64)
        return img
    args = [_load(a["npy"]) if isinstance(a, dict) else a for a in call["args"]]
    if "canvas" in call:
        args[call["canvas"]] = np.ones(call["canvas_shape"], dtype=np.float64)
    result = func(*args)
    if result is None and "canvas" in call:
        return args[call["canvas"]]
    if result is None:
        raise TypeError(f"{call['func']} returned None")
    return result


def _alarm(signum, frame):
    raise CallTimeout()


def main(spec_path):
    with open(spec_path, encoding="utf-8") as f:
        spec = json.load(f)
    out = spec["out"]
    _state["out_dir"] = os.path.abspath(out)
    global _READ_ROOTS, _WRITE_ROOTS
    _READ_ROOTS = tuple(spec.get("read_roots", _READ_ROOTS))
    _WRITE_ROOTS = tuple(spec.get("write_roots", _WRITE_ROOTS))
    status = _Status(spec["result_fd"])
    _install_stubs()
    sys.path.insert(0, spec["submission"])
    os.chdir("/tmp")
    sys.addaudithook(_audit)
    signal.signal(signal.SIGALRM, _alarm)
    status.write(event="start", call="import")
    functions, failure, skipped = _import_functions(spec)
    if failure is not None:
        status.write(event="end", call="import", **failure)
        return
    status.write(event="end", call="import", status="ok", skipped=skipped)
    for call in spec["calls"]:
        _one_call(call, functions, spec, status)


class _DemoFreeLoader(importlib.machinery.SourceFileLoader):
    """Imports a student's module without its top-level demo code (calls, loops, `if` blocks such
    as `if __name__ == "__main__":`, which load hard-coded paths or open windows): only imports,
    definitions, assignments and try blocks run. Used when the plain import failed."""
    skipped = []
    _KEEP = (ast.Import, ast.ImportFrom, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef,
             ast.Assign, ast.AnnAssign, ast.AugAssign, ast.Try)

    def get_code(self, fullname):
        # Always from the source: a cached .pyc of the plain import would bring the demo back.
        path = self.get_filename(fullname)
        return self.source_to_code(self.get_data(path), path)

    def source_to_code(self, data, path, *, _optimize=-1):
        tree = ast.parse(data, path)
        kept = []
        for statement in tree.body:
            where = f"{os.path.basename(path)}:{statement.lineno}"
            if isinstance(statement, (ast.Assign, ast.AnnAssign, ast.AugAssign)):
                # `data = np.load("/home/me/hw1.npy")` at the top: its failure must not stop the
                # definitions after it.
                guard = ast.parse("try:\n    pass\nexcept BaseException:\n    pass").body[0]
                guard.body = [statement]
                kept.append(ast.copy_location(guard, statement))
            elif isinstance(statement, self._KEEP):
                kept.append(statement)
            else:
                self.skipped.append(where)
        tree.body = kept
        return compile(ast.fix_missing_locations(tree), path, "exec", dont_inherit=True)


def _import_module(module, spec):
    """A module by name, or by path when its file name has dots (hw1.final.py): loaded with the
    loader the import is using (the demo-free one on the second try)."""
    path = spec.get("module_paths", {}).get(module)
    if path is None:
        return importlib.import_module(module)
    if module in sys.modules:
        return sys.modules[module]
    loader_class = _DemoFreeLoader if _state.get("demo_free") else \
        importlib.machinery.SourceFileLoader
    path = os.path.join(spec["submission"], path)
    module_spec = importlib.util.spec_from_file_location(module, path,
                                                         loader=loader_class(module, path))
    loaded = importlib.util.module_from_spec(module_spec)
    sys.modules[module] = loaded
    module_spec.loader.exec_module(loaded)
    return loaded


def _import_all(spec):
    functions = {}
    for name, module in spec["functions"].items():
        # "module:name": the student's function has another year's name (shade_triangle).
        module, _, own = module.partition(":")
        function = getattr(_import_module(module, spec), own or name, None)
        if callable(function):
            functions[name] = function
    return functions


def _import_functions(spec):
    """The student's functions, imported with the sandbox's rules armed. A failure that demo code
    may explain (an exception, a forbidden read of a hard-coded path) is retried without the
    top-level demo code; sys.exit, os._exit and time-outs are verdicts at once."""
    before = set(sys.modules)
    _state["armed"] = True
    try:
        signal.setitimer(signal.ITIMER_REAL, spec.get("import_timeout", 10))
        try:
            return _import_all(spec), None, []
        except (Exception, Forbidden) as first:
            first_verdict = _verdict(first)
        for name in set(sys.modules) - before:
            del sys.modules[name]
        sys.path_hooks.insert(0, importlib.machinery.FileFinder.path_hook(
            (_DemoFreeLoader, importlib.machinery.SOURCE_SUFFIXES)))
        sys.path_importer_cache.clear()
        _state["demo_free"] = True
        _state["forbidden"] = None
        try:
            return _import_all(spec), None, _DemoFreeLoader.skipped
        except (Exception, Forbidden):
            return None, first_verdict, []
    except BaseException as e:  # noqa: B902 - every way an import can fail is a verdict
        return None, _verdict(e), []
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        _state["armed"] = False


def _verdict(e):
    if isinstance(e, Forbidden):
        return {"status": "forbidden", "detail": f"tried to {e.args[0]}"}
    if isinstance(e, CallTimeout):
        return {"status": "timeout", "detail": "the call ran past its time limit"}
    if isinstance(e, MemoryError):
        return {"status": "memory", "detail": "ran out of memory (MemoryError)"}
    if isinstance(e, SystemExit):
        return {"status": "crashed", "detail": f"called sys.exit({e.code!r})"}
    if isinstance(e, KeyboardInterrupt):
        return {"status": "crashed", "detail": "raised KeyboardInterrupt"}
    tb = traceback.format_exception(type(e), e, e.__traceback__)
    detail = _last_lines("".join(tb), 12)
    if _state["forbidden"]:
        return {"status": "forbidden", "detail": f"tried to {_state['forbidden']}"}
    return {"status": "error", "detail": detail}


def _one_call(call, functions, spec, status):
    status.write(event="start", call=call["id"])
    _state["forbidden"] = None
    _state["armed"] = True
    try:
        signal.setitimer(signal.ITIMER_REAL, call.get("timeout", 10))
        value = _run_call(call, functions, spec)
        signal.setitimer(signal.ITIMER_REAL, 0)
        _state["armed"] = False
        array = _as_float_array(value, call["func"])
        note = "list" if isinstance(value, list) else type(value).__name__
        if array.ndim > 3 or array.size > call.get("max_values", array.size):
            raise ValueError(f"{call['func']} returned an array of shape {array.shape}: more "
                             f"than the {call.get('max_values')} numbers this call may return")
        status.write(array.astype("<f8").tobytes(), event="end", call=call["id"], status="ok",
                     shape=list(array.shape), returned=note)
    except BaseException as e:  # noqa: B902 - the student's failure is the call's verdict
        signal.setitimer(signal.ITIMER_REAL, 0)
        _state["armed"] = False
        if _state["forbidden"] and not isinstance(e, (CallTimeout, MemoryError)):
            e = Forbidden(_state["forbidden"])
        status.write(event="end", call=call["id"], **_verdict(e))


if __name__ == "__main__":
    main(sys.argv[1])
