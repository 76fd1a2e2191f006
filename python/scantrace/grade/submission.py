"""A submission: a directory of .py files, one .py file, or a .zip of them, staged into a temp
directory (only .py files, size-limited) and searched — without running anything — for the
course's functions by name."""

import ast
import dataclasses
import errno
import os
import pathlib
import shutil
import stat
import tempfile
import zipfile
import zlib

from . import signatures

FUNCTIONS = ("vector_interp", "f_shading", "g_shading", "render_img")
MAX_FILES = 200
MAX_BYTES = 2_000_000
MAX_TOTAL = 20_000_000
MAX_DEPTH = 32


class SubmissionError(ValueError):
    """The submission cannot be graded at all (exit status 1)."""


@dataclasses.dataclass
class Submission:
    name: str
    root: pathlib.Path                   # the staged copy the sandbox sees
    functions: dict                      # function name -> module name
    notes: list                          # what the grader could not use, naming file and line
    staged: pathlib.Path | None = None   # the temporary folder holding root, however deep

    def close(self):
        shutil.rmtree(self.staged or self.root.parent, ignore_errors=True)


def _skip_dir(name):
    # Hidden folders, caches, and folders named like a module file (pkg.py/): staging one would
    # give a module and a folder of one name (a zip holding hw1.py and hw1.py/extra.py).
    return name.startswith(".") or name == "__pycache__" or name == "__MACOSX" \
        or name.endswith(".py")


def _write_new(target, data, budget):
    budget[0] -= len(data)
    if budget[0] < 0:
        raise SubmissionError(f"more than {MAX_TOTAL} bytes of .py files in all")
    target.parent.mkdir(parents=True, exist_ok=True)
    with open(target, "xb") as f:   # x: never through a link, never over another file
        f.write(data)


def _zip_kind(member):
    """What a zip member is by its Unix mode (external_attr's high bits): zip tools store links
    (unzip -y / zip --symlinks) as members whose data is the link's target."""
    mode = member.external_attr >> 16
    if stat.S_IFMT(mode) == 0 or stat.S_ISREG(mode):   # 0: no type stored (Windows zips)
        return None
    return "a symbolic link" if stat.S_ISLNK(mode) else "not a regular file"


def _open_regular(path):
    """The file given, opened without following a link or blocking on a FIFO."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError as e:
        raise SubmissionError(f"{path}: cannot be opened ({e.strerror})") from None
    if not stat.S_ISREG(os.fstat(fd).st_mode):
        os.close(fd)
        raise SubmissionError(f"{path}: not a regular file")
    return os.fdopen(fd, "rb")


def _stage_zip(path, root, notes):
    with _open_regular(path) as f:
        try:
            archive = zipfile.ZipFile(f)
        except (zipfile.BadZipFile, OSError, ValueError, EOFError) as e:
            raise SubmissionError(f"{path}: not a readable zip file ({e})") from None
        with archive:
            _stage_members(path, archive, root, notes)


def _stage_members(path, archive, root, notes):
    budget = [MAX_TOTAL]
    members = [m for m in archive.infolist() if m.filename.endswith(".py") and not m.is_dir()]
    if len(members) > MAX_FILES:
        raise SubmissionError(f"{path}: {len(members)} .py files (at most {MAX_FILES})")
    for m in members:
        parts = pathlib.PurePosixPath(m.filename).parts
        if m.filename.startswith("/") or ".." in parts:
            raise SubmissionError(f"{path}: {m.filename}: a path outside the archive")
        if any(_skip_dir(part) for part in parts[:-1]) or parts[-1].startswith("."):
            if any(part.endswith(".py") for part in parts[:-1]):
                notes.append(f"{m.filename}: in a folder named like a module, not staged")
            continue
        if _zip_kind(m):
            notes.append(f"{m.filename}: {_zip_kind(m)}, not staged")
            continue
        if m.file_size > MAX_BYTES:
            raise SubmissionError(f"{path}: {m.filename}: {m.file_size} bytes (at most "
                                  f"{MAX_BYTES})")
        try:
            data = archive.read(m)
        except (zipfile.BadZipFile, zlib.error, OSError, EOFError, ValueError,
                NotImplementedError, RuntimeError) as e:
            # A bad CRC, an unknown compression, an encrypted member.
            raise SubmissionError(f"{path}: {m.filename}: cannot be read ({e})") from None
        try:
            _write_new(root.joinpath(*parts), data, budget)
        except FileExistsError:
            notes.append(f"{m.filename}: in the zip twice; the first is staged")
        except OSError as e:   # a name too long for the file system, a part that is a file
            notes.append(f"{m.filename}: cannot be staged ({e.strerror})")


def _read_regular(name, dir_fd, shown):
    """A file's bytes, if it is a regular file: opened without following a link and without
    blocking on a FIFO, checked with fstat, read no further than the limit."""
    try:
        fd = os.open(name, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK, dir_fd=dir_fd)
    except OSError as e:
        return None, ("a symbolic link" if e.errno == errno.ELOOP else
                      f"cannot be opened ({e.strerror})")
    with os.fdopen(fd, "rb") as f:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            return None, "not a regular file"
        if info.st_nlink > 1:
            # A hard link may be another's file (as root, any file of this file system).
            return None, f"a hard link ({info.st_nlink} names)"
        if info.st_size > MAX_BYTES:
            raise SubmissionError(f"{shown}: {info.st_size} bytes (at most {MAX_BYTES})")
        data = f.read(MAX_BYTES + 1)
    if len(data) > MAX_BYTES:
        raise SubmissionError(f"{shown}: more than {MAX_BYTES} bytes")
    return data, None


def _stage_dir(path, root, notes):
    """The folder's .py files, walked without following links (os.fwalk: every name is opened
    relative to its folder's descriptor, so no path is followed twice)."""
    budget, count = [MAX_TOTAL], 0
    for folder, dirs, files, dir_fd in os.fwalk(path, follow_symlinks=False):
        rel = pathlib.Path(folder).relative_to(path)
        notes += [f"{rel / d}/: a folder named like a module, not staged" for d in dirs
                  if d.endswith(".py")]
        if len(rel.parts) >= MAX_DEPTH and dirs:
            # fwalk recurses and holds a descriptor a level: 5000 nested folders would be a
            # RecursionError (or run out of descriptors) in the grader.
            notes.append(f"{rel}/: folders deeper than {MAX_DEPTH} levels, not staged")
            dirs[:] = []
        dirs[:] = [d for d in dirs if not _skip_dir(d)]
        for name in sorted(files):
            if not name.endswith(".py") or name.startswith("."):
                continue
            count += 1
            if count > MAX_FILES:
                raise SubmissionError(f"{path}: more than {MAX_FILES} .py files")
            data, why = _read_regular(name, dir_fd, path / rel / name)
            if why:
                notes.append(f"{rel / name}: {why}, not staged")
                continue
            _write_new(root / rel / name, data, budget)


def _stage_file(path, root):
    """One .py file given as the submission: a regular file, not a link."""
    data, why = _read_regular(str(path), None, path)
    if why:
        raise SubmissionError(f"{path}: {why}")
    _write_new(root / path.name, data, [MAX_TOTAL])


def _common_root(root):
    """The folder the student's files live in (a zip often holds one folder)."""
    while True:
        entries = list(root.iterdir())
        if len(entries) == 1 and entries[0].is_dir():
            root = entries[0]
        else:
            return root


def _module_name(path, root):
    rel = path.relative_to(root).with_suffix("")
    return ".".join(rel.parts)


class Found(str):
    """Where a course function is taken from, as the harness imports it: "module", or
    "module:name" when the student's function has another year's name (shade_triangle for
    f_shading). `adapter` (signatures.adapter's dict, or None: called as is) and `api` (the
    one-line note of another year's API, or "") ride along for the battery."""

    def __new__(cls, value, adapter=None, api=""):
        found = super().__new__(cls, value)
        found.adapter, found.api = adapter, api
        return found


def _parse(root, notes):
    """module name -> {name: FunctionDef} of its top-level functions, and the strings the
    submission compares with anywhere (its shading values). Nothing is run."""
    modules, strings = {}, set()
    for path in sorted(root.rglob("*.py")):
        rel = path.relative_to(root)
        try:
            tree = ast.parse(path.read_bytes(), str(rel))
        except SyntaxError as e:
            notes.append(f"{rel}:{e.lineno}: syntax error ({e.msg}); this file is not used")
            continue
        except (ValueError, RecursionError, MemoryError) as e:
            # A NUL byte; an expression nested too deep for the parser (10 KB: RecursionError,
            # 200 KB: MemoryError).
            notes.append(f"{rel}: cannot be parsed ({type(e).__name__}: {str(e)[:200]}); this "
                         "file is not used")
            continue
        modules[_module_name(path, root)] = {n.name: n for n in tree.body
                                             if isinstance(n, ast.FunctionDef)}
        strings |= signatures.compared_strings(tree)
    return modules, strings


def _provided(defs):
    """course function -> the name of the student's function providing it in one module: its
    own name first, then another year's (signatures.ALIASES)."""
    provided = {}
    for f in FUNCTIONS:
        name = next((n for n in (f, *signatures.ALIASES[f]) if n in defs), None)
        if name is not None:
            provided[f] = name
    return provided


def _find(root, module_override):
    """The course's four functions: all taken from one module — the one defining the most of
    them (ties: the shortest name), so two copies of the code (hw1.py and hw1_old.py, a notebook
    export beside the module) are never mixed — and from other modules only those it lacks.
    Each signature is read: another year's API goes through an adapter, said in one note."""
    notes = []
    modules, strings = _parse(root, notes)
    provides = {m: _provided(defs) for m, defs in modules.items()}
    if module_override:
        provides = {module_override: provides.get(module_override, {})}

    def rank(m):
        return (-len(provides[m]), len(m), m)

    holders = sorted((m for m in provides if provides[m]), key=rank)
    functions, api, unfit = {}, [], []
    for f in FUNCTIONS:
        m = next((m for m in holders if f in provides[m]), None)
        if m is None:
            if module_override:
                functions[f] = Found(module_override)
            notes.append(f"no function `{f}` in any file of the submission")
            continue
        name = provides[m][f]
        adapter, note = signatures.adapter(f, name, modules[m][name],
                                           signatures.shading_values(strings))
        functions[f] = Found(m if name == f else f"{m}:{name}", adapter, note)
        if note and note not in api + unfit:
            (api if adapter else unfit).append(note)
    copies = [m for m in holders[1:] if set(provides[m]) & set(provides[holders[0]])]
    if copies:
        notes.append(f"the course's functions are defined in {', '.join(holders[:1] + copies)}"
                     f": all are taken from {holders[0]} (the module defining the most of them;"
                     " ties: the shortest name)")
    if api:
        notes.append("another year's API, graded through an adapter: " + "; ".join(api))
    notes += unfit
    return functions, notes


def stage(path, module=None):
    """Copies the submission's .py files (regular files only: no link, FIFO or device is followed
    or read) into a new temporary folder, and finds the functions in them."""
    path = pathlib.Path(path)
    try:
        kind = os.lstat(path).st_mode
    except OSError:
        raise SubmissionError(f"{path}: no such file or directory") from None
    if stat.S_ISLNK(kind):
        raise SubmissionError(f"{path}: a symbolic link (give the file or folder itself)")
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="scantrace-submission-"))
    root = tmp / "submission"
    root.mkdir()
    notes = []
    try:
        if stat.S_ISDIR(kind):
            _stage_dir(path, root, notes)
        elif path.suffix == ".zip":
            _stage_zip(path, root, notes)
        elif path.suffix == ".py":
            _stage_file(path, root)
        else:
            raise SubmissionError(f"{path}: expected a directory, a .py file or a .zip")
        root = _common_root(root)
        if not any(root.rglob("*.py")):
            raise SubmissionError(f"{path}: no .py file in the submission"
                                  + "".join(f"; {n}" for n in notes[:5]))
        for p in [root, *root.rglob("*")]:
            p.chmod(0o755 if p.is_dir() else 0o644)
        tmp.chmod(0o755)
        functions, found = _find(root, module)
        notes += found
        if not functions or (module is None and not set(functions) & set(FUNCTIONS)):
            raise SubmissionError(f"{path}: none of {', '.join(FUNCTIONS)} is defined in its "
                                  ".py files" + "".join(f"; {n}" for n in notes
                                                        if not n.startswith("no function")))
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    name = path.stem if path.suffix in (".zip", ".py") and not stat.S_ISDIR(kind) else path.name
    return Submission(name, root, functions, notes, tmp)
