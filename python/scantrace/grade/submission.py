"""A submission: a directory of .py files, one .py file, or a .zip of them, staged into a temp
directory (only .py files, size-limited) and searched — without running anything — for the
course's functions by name."""

import ast
import dataclasses
import pathlib
import shutil
import tempfile
import zipfile

from . import signatures

FUNCTIONS = ("vector_interp", "f_shading", "g_shading", "render_img")
MAX_FILES = 200
MAX_BYTES = 2_000_000


class SubmissionError(ValueError):
    """The submission cannot be graded at all (exit status 1)."""


@dataclasses.dataclass
class Submission:
    name: str
    root: pathlib.Path                   # the staged copy the sandbox sees
    functions: dict                      # function name -> module name
    notes: list                          # what the grader could not use, naming file and line

    def close(self):
        shutil.rmtree(self.root.parent, ignore_errors=True)


def _stage_zip(path, root):
    try:
        archive = zipfile.ZipFile(path)
    except (zipfile.BadZipFile, OSError) as e:
        raise SubmissionError(f"{path}: not a readable zip file ({e})") from None
    with archive:
        members = [m for m in archive.infolist() if m.filename.endswith(".py")
                   and not m.is_dir() and "__MACOSX" not in m.filename]
        if len(members) > MAX_FILES:
            raise SubmissionError(f"{path}: {len(members)} .py files (at most {MAX_FILES})")
        for m in members:
            parts = pathlib.PurePosixPath(m.filename).parts
            if m.filename.startswith("/") or ".." in parts:
                raise SubmissionError(f"{path}: {m.filename}: a path outside the archive")
            if m.file_size > MAX_BYTES:
                raise SubmissionError(f"{path}: {m.filename}: {m.file_size} bytes (at most "
                                      f"{MAX_BYTES})")
            target = root.joinpath(*parts)
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(archive.read(m))


def _stage_dir(path, root):
    files = [p for p in path.rglob("*.py") if not any(part.startswith(".") or part ==
                                                       "__pycache__" for part in
                                                       p.relative_to(path).parts)]
    if len(files) > MAX_FILES:
        raise SubmissionError(f"{path}: {len(files)} .py files (at most {MAX_FILES})")
    for p in files:
        if p.stat().st_size > MAX_BYTES:
            raise SubmissionError(f"{p}: {p.stat().st_size} bytes (at most {MAX_BYTES})")
        target = root / p.relative_to(path)
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(p, target)


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
        except ValueError as e:
            notes.append(f"{rel}: cannot be parsed ({e}); this file is not used")
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
    path = pathlib.Path(path)
    if not path.exists():
        raise SubmissionError(f"{path}: no such file or directory")
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="scantrace-submission-"))
    root = tmp / "submission"
    root.mkdir()
    try:
        if path.is_dir():
            _stage_dir(path, root)
        elif path.suffix == ".zip":
            _stage_zip(path, root)
        elif path.suffix == ".py":
            shutil.copyfile(path, root / path.name)
        else:
            raise SubmissionError(f"{path}: expected a directory, a .py file or a .zip")
        root = _common_root(root)
        if not any(root.rglob("*.py")):
            raise SubmissionError(f"{path}: no .py file in the submission")
        for p in [root, *root.rglob("*")]:
            p.chmod(0o755 if p.is_dir() else 0o644)
        tmp.chmod(0o755)
        functions, notes = _find(root, module)
        if not functions or (module is None and not set(functions) & set(FUNCTIONS)):
            raise SubmissionError(f"{path}: none of {', '.join(FUNCTIONS)} is defined in its "
                                  ".py files" + "".join(f"; {n}" for n in notes
                                                        if not n.startswith("no function")))
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    name = path.stem if path.suffix in (".zip", ".py") else path.name
    return Submission(name, root, functions, notes)
