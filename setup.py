"""The build step of `pip install .` and `python3 -m build --wheel`: the C++ extension modules are
built by the project's own CMake (the build is defined there once), then copied into the wheel.

    pip install --no-build-isolation .       (into a venv made with --system-site-packages)

Environment:
    SCANTRACE_CMAKE_BUILD_DIR   the CMake build directory. Default: outside the clone, in
                                ${XDG_CACHE_HOME:-~/.cache}/scantrace/python-KEY/build, KEY naming
                                the clone's path (the install writes nothing into the clone; the
                                directory is kept, so a second install rebuilds only what
                                changed). python-KEY/ also holds a link to each of the clone's
                                top-level entries and CMake is given python-KEY/ as the source:
                                a compile then sees the paths a clone's own build/ sees
                                (../../src/x.cpp), so ccache, with python-KEY/ as its base
                                directory, finds the objects of any clone's build (scripts/build.sh,
                                CI, an earlier pip install elsewhere). An existing build directory
                                given here is built as it is configured, not reconfigured.
    SCANTRACE_PYTHON_OPENCV=1   also build _scantrace_cv (explain's video, diff of PNG/JPEG/BMP
                                files), which links OpenCV; without it the package loads no OpenCV.
    SCANTRACE_JOBS              parallel compile jobs (default: the number of cores).

The compile's progress goes to the terminal (/dev/tty, since pip captures the build's output
unless -v is given) and to the build's output.
"""

import hashlib
import os
import pathlib
import re
import shutil
import subprocess
import sys
import time


def refuse_an_interpreter_that_cannot_build():
    """Fails at once, with the one command that works, when this interpreter cannot build or run
    scantrace without a package index: a pyenv or conda python3 (or a venv made from one) has no
    setuptools, wheel or numpy, and `pip install --no-build-isolation .` then failed late ("invalid
    command 'bdist_wheel'", then no numpy). An isolated build (plain `pip install .` with an
    index, or `python -m build`) brings setuptools and wheel itself, and pip installs numpy as a
    dependency: numpy is then not needed here."""
    import importlib.util
    isolated = any("pip-build-env" in p or "build-env-" in p for p in sys.path)
    needed = ("setuptools", "wheel") + (() if isolated else ("numpy",))
    missing = [m for m in needed if importlib.util.find_spec(m) is None]
    if not missing:
        return
    sys.exit(
        f"scantrace: {sys.executable} has no {', '.join(missing)} (a pyenv or conda python3?), "
        "and without a package index pip cannot fetch them.\n"
        "Build with Debian's python3, which has numpy, setuptools and wheel (deps.sh installs "
        "them):\n"
        "    /usr/bin/python3 -m venv --system-site-packages ~/venvs/scantrace\n"
        "    ~/venvs/scantrace/bin/pip install --no-build-isolation .\n"
        "With a package index, plain `pip install .` works from any python3 (it fetches "
        "setuptools, wheel and numpy).")


refuse_an_interpreter_that_cannot_build()

from setuptools import Extension, setup  # noqa: E402 (after the check: it may be missing)
from setuptools.command.build_ext import build_ext  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent


def default_work_dir():
    """This clone's directory in the user's cache, one per clone (a build directory holds its
    absolute paths): the links to the clone's entries and the CMake build directory build/."""
    cache = pathlib.Path(os.environ.get("XDG_CACHE_HOME") or pathlib.Path.home() / ".cache")
    key = hashlib.sha256(str(ROOT).encode()).hexdigest()[:12]
    return cache / "scantrace" / f"python-{key}"


def mirror_clone(work):
    """Links work/NAME -> the clone's NAME for each of the clone's top-level entries (but .git and
    build, the name of the build directory beside them), and drops links to entries that are gone.

    Why: ccache hashes a compile's paths, relative to its base directory when they lie below it.
    A clone's own build (scripts/build.sh, CI: base directory the clone, build/ in it) compiles
    src/x.cpp as ../../src/x.cpp from build/src. A build directory elsewhere would see the clone
    under another relative path, different for every clone, and every compile would miss (as it
    did: a fresh clone's install compiled all of it, 294 s of CPU). Seen through these links from
    work/build, the paths are the same as in any clone's build/, generated unity sources' #include
    lines included (ccache's preprocessed hash rewrites them relative too)."""
    work.mkdir(parents=True, exist_ok=True)
    wanted = {p.name for p in ROOT.iterdir() if p.name not in (".git", "build")}
    for link in work.iterdir():
        if link.is_symlink() and link.name not in wanted:
            link.unlink()
    for name in sorted(wanted):
        link, target = work / name, ROOT / name
        if link.is_symlink() and os.readlink(link) == str(target):
            continue
        if link.is_symlink():
            link.unlink()
        link.symlink_to(target)


CUSTOM_BUILD = os.environ.get("SCANTRACE_CMAKE_BUILD_DIR")
# WORK: the source directory CMake is given (the clone itself for a build directory of the user's).
WORK = ROOT if CUSTOM_BUILD else default_work_dir()
BUILD = pathlib.Path(CUSTOM_BUILD).resolve() if CUSTOM_BUILD else WORK / "build"
WITH_OPENCV = os.environ.get("SCANTRACE_PYTHON_OPENCV", "0") not in ("", "0", "OFF", "off")


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(scantrace VERSION ([0-9.]+)", text).group(1)


class Progress:
    """Echoes the build's output, and shows CMake's "[ 45%] Building ..." lines on the terminal."""

    def __init__(self):
        try:
            self.tty = open("/dev/tty", "w")  # noqa: SIM115 (closed in close())
        except OSError:
            self.tty = None
        self.start = time.monotonic()

    def say(self, text, final=False):
        if self.tty:
            line = f"scantrace: {text}"[:110]
            self.tty.write("\r\x1b[K" + line + ("\n" if final else ""))
            self.tty.flush()
        print(f"scantrace: {text}", flush=True)

    def run(self, cmd, what):
        self.say(f"{what}: {' '.join(cmd[:3])} ...")
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             bufsize=1)
        tail = []
        for line in p.stdout:
            sys.stdout.write(line)
            tail = (tail + [line])[-30:]
            m = re.match(r"\[\s*(\d+)%\]\s*(.*)", line)
            if m and self.tty:
                self.tty.write(f"\r\x1b[Kscantrace: {what} [{m.group(1):>3}%] "
                               f"{m.group(2).strip()[:70]}")
                self.tty.flush()
        if p.wait() != 0:
            self.say(f"{what} failed (exit {p.returncode}); its last lines:", final=True)
            sys.stderr.write("".join(tail))
            raise SystemExit(f"scantrace: {what} failed: {' '.join(cmd)}")

    def close(self):
        self.say(f"C++ modules built in {time.monotonic() - self.start:.0f} s", final=True)
        if self.tty:
            self.tty.close()


class CMakeBuild(build_ext):
    """Configures the CMake project once, builds every module's target, copies the modules."""

    def run(self):
        progress = Progress()
        if WORK != ROOT:
            mirror_clone(WORK)
            # The base directory covers the links and build/; set here, not left to the user's
            # environment, whose CCACHE_BASEDIR would name the clone (scripts/build.sh's).
            os.environ["CCACHE_BASEDIR"] = str(WORK)
        else:
            os.environ.setdefault("CCACHE_BASEDIR", str(ROOT))
        os.environ.setdefault("CCACHE_NOHASHDIR", "true")  # as .ci/run: no -g, but be sure
        if not (BUILD / "CMakeCache.txt").exists():
            BUILD.mkdir(parents=True, exist_ok=True)
            cmd = ["cmake", "-S", str(WORK), "-B", str(BUILD), "-DCMAKE_BUILD_TYPE=Release",
                   "-DSCANTRACE_BUILD_TESTS=OFF", "-DSCANTRACE_BUILD_BENCH=OFF",
                   "-DSCANTRACE_BUILD_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}",
                   f"-DSCANTRACE_PYTHON_OPENCV={'ON' if WITH_OPENCV else 'OFF'}"]
            # As scripts/build.sh: ccache makes a build in another clone of the same sources cheap.
            if shutil.which("ccache"):
                cmd.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
            progress.run(cmd, "configuring")
        jobs = os.environ.get("SCANTRACE_JOBS", str(os.cpu_count() or 2))
        env_targets = [ext.name.split(".")[-1] for ext in self.extensions]
        progress.run(["cmake", "--build", str(BUILD), "-j", jobs, "--target", *env_targets],
                     "compiling the C++ core")
        progress.close()
        for ext in self.extensions:
            self.copy_module(ext)

    def copy_module(self, ext):
        name = ext.name.split(".")[-1]
        built = sorted((BUILD / "python" / "scantrace").glob(f"{name}.*.so")) or \
            sorted((BUILD / "python" / "scantrace").glob(f"{name}.so"))
        if not built:
            raise SystemExit(f"scantrace: {name} was not built in {BUILD}/python/scantrace "
                             "(is SCANTRACE_BUILD_PYTHON off in that build directory?)")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], target)


extensions = [Extension("scantrace._scantrace", sources=[])]
if WITH_OPENCV:
    extensions.append(Extension("scantrace._scantrace_cv", sources=[]))

BUILD.mkdir(parents=True, exist_ok=True)
setup(
    version=project_version(),
    ext_modules=extensions,
    cmdclass={"build_ext": CMakeBuild},
    # setuptools' own files (egg-info, build/) go into the build directory, not the clone.
    options={"egg_info": {"egg_base": str(BUILD)},
             "build": {"build_base": str(BUILD / "setuptools")}},
)
