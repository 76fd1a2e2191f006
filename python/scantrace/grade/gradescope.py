"""`scantrace grade --gradescope-zip OUT.zip`: a Gradescope autograder.

The zip holds, at its root (where Gradescope looks for them):
  setup.sh         run once as root when Gradescope builds the autograder's image: installs the
                   Ubuntu packages scantrace needs to build (and bubblewrap), builds the Python
                   package from the source below into /autograder/source/build/python, and
                   (unless --no-sandbox) fails there if bwrap cannot make its namespaces;
  run_autograder   run as root for each submission: grades /autograder/submission with the
                   options baked in below and leaves /autograder/results/results.json (always:
                   when the grader itself fails, a results.json saying why, score 0);
  grade_args       the grading options given with --gradescope-zip, one argument a line;
  rubric.toml      the --rubric, when given;
  scene/NAME       the --scene, when given;
  scantrace/       the project's source (its git-tracked files).

The hidden seed, rubric and scene stay under /autograder/source, which the sandbox does not show
to the student's code. $SCANTRACE_AUTOGRADER_ROOT replaces /autograder (the tests lay out a
temporary directory that way), $SCANTRACE_PYTHONPATH the built package's folder.
"""

import os
import pathlib
import stat
import subprocess
import tempfile
import zipfile

# The Ubuntu packages of the build (scripts/deps.sh's demo list: the libraries CMakeLists.txt
# finds; OpenCV's headers are needed to configure even though the Python module links none of
# its video or window parts; libpng and libjpeg, which grade/ finds, come with libopencv-dev but
# are named as used), the Python module's (pybind11, numpy), and the sandbox's. Each name is
# checked against Ubuntu 24.04 and 22.04 as docs/grading.md says ("setup.sh's packages").
UBUNTU_PACKAGES = ("cmake g++ make pkg-config libspdlog-dev nlohmann-json3-dev libsimdjson-dev "
                   "libopencv-dev libdeflate-dev libcli11-dev libtinyobjloader-dev libmatio-dev "
                   "libxcb1-dev libhwy-dev libpng-dev libjpeg-dev pybind11-dev python3-dev "
                   "python3-numpy bubblewrap")

SETUP_SH = r"""#!/usr/bin/env bash
# Gradescope's autograder setup (made by `scantrace grade --gradescope-zip`, docs/grading.md):
# run once, as root, when Gradescope builds the autograder's image. Choose the Ubuntu 24.04 base
# image: the grader needs Python >= 3.11 (tomllib) and the build the packages below.
#   SCANTRACE_SETUP_SKIP_APT=1   do not call apt-get (the packages are already there)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
packages=(@PACKAGES@)
if [ -z "${SCANTRACE_SETUP_SKIP_APT:-}" ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y --no-install-recommends "${packages[@]}"
fi
if ! /usr/bin/python3 -c 'import sys; sys.exit(sys.version_info < (3, 11))'; then
  echo "setup.sh: the grader needs Python >= 3.11 (tomllib); $(/usr/bin/python3 --version) is" \
       "installed: choose Gradescope's Ubuntu 24.04 base image" >&2
  exit 1
fi
# Only the Python package's target: no tests, benchmarks or command-line programs.
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$PWD/scantrace"
fi
cmake -S scantrace -B build -DCMAKE_BUILD_TYPE=Release -DSCANTRACE_BUILD_TESTS=OFF \
      -DSCANTRACE_BUILD_BENCH=OFF -DSCANTRACE_BUILD_PYTHON=ON \
      -DPython_EXECUTABLE=/usr/bin/python3 "${launcher[@]}"
cmake --build build -j"$(nproc)" --target _scantrace
PYTHONPATH="$PWD/build/python" /usr/bin/python3 -c 'import scantrace.grade.grader'
@SANDBOX_CHECK@echo "setup.sh: scantrace's grader is built in $PWD/build/python"
"""

# setup.sh's last step (a constant of its own so the tests can run it against a stub package).
SANDBOX_CHECK = r"""# The sandbox, checked now with the grader's own test (unless the zip was made
# with --no-sandbox): an image where bwrap cannot make its namespaces fails here, once, with the
# reason, rather than giving every student a score of 0 later.
if ! grep -qx -- '--no-sandbox' grade_args; then
  problem=$(PYTHONPATH="$PWD/build/python" /usr/bin/python3 -c \
    'from scantrace.grade.sandbox import sandbox_problem; print(sandbox_problem() or "")')
  if [ -n "$problem" ]; then
    echo "setup.sh: the grader's sandbox cannot run in this image: $problem. Allow user" \
         "namespaces, or make the zip with --no-sandbox (then the container is the only" \
         "isolation: docs/grading.md)" >&2
    exit 1
  fi
fi
"""

RUN_AUTOGRADER = r"""#!/usr/bin/env bash
# Gradescope runs this for each submission, as root, in that submission's own container (made by
# `scantrace grade --gradescope-zip`, docs/grading.md). It grades $ROOT/submission with the
# options in grade_args and leaves $ROOT/results/results.json, always: when the grader cannot
# grade at all (the sandbox refused, the package missing), a results.json with score 0 and the
# grader's message. ROOT is /autograder, or $SCANTRACE_AUTOGRADER_ROOT.
set -uo pipefail
root="${SCANTRACE_AUTOGRADER_ROOT:-/autograder}"
source_dir="$root/source"
results="$root/results"
cd "$source_dir" || exit 1
mapfile -t grade_args < grade_args
package="${SCANTRACE_PYTHONPATH:-$source_dir/build/python}"
export PYTHONPATH="$package${PYTHONPATH:+:$PYTHONPATH}"
mkdir -p "$results"
/usr/bin/python3 -m scantrace.grade "$root/submission" -o "$results" --quiet "${grade_args[@]}" \
  2> "$results/grader_stderr.txt"
status=$?
cat "$results/grader_stderr.txt" >&2
if [ ! -s "$results/results.json" ]; then
  # The grader wrote nothing: say why to the student and the instructor (written whole).
  /usr/bin/python3 - "$results" "$status" <<'EOF'
import json, os, pathlib, re, sys
results, status = pathlib.Path(sys.argv[1]), sys.argv[2]
why = (results / "grader_stderr.txt").read_text(errors="replace").strip()[-4000:]
# Student text may be in it: control characters escaped, in a fence longer than any backticks.
why = re.sub("[\x00-\x08\x0b-\x1f\x7f-\x9f]", lambda m: f"\\x{ord(m.group()):02x}", why)
fence = "`" * max([3] + [len(r) + 1 for r in re.findall("`+", why)])
doc = {"score": 0, "output": f"Not graded: the grader failed (exit status {status}):\n\n"
                             f"{fence}text\n{why}\n{fence}\n",
       "output_format": "md", "tests": []}
(results / ".results.json").write_text(json.dumps(doc, indent=1))
os.replace(results / ".results.json", results / "results.json")
EOF
fi
exit 0
"""


class ZipError(ValueError):
    pass


def find_source(given=None):
    """The scantrace clone to put in the zip: --source, $SCANTRACE_SOURCE_DIR, or the folder
    above this package that holds the project's CMakeLists.txt (python/scantrace/grade in a
    clone, build/python/scantrace/grade in its build tree)."""
    candidates = [given] if given else []
    if os.environ.get("SCANTRACE_SOURCE_DIR") and not given:
        candidates.append(os.environ["SCANTRACE_SOURCE_DIR"])
    if not candidates:
        candidates = list(pathlib.Path(__file__).resolve().parents)
    for c in candidates:
        c = pathlib.Path(c)
        lists = c / "CMakeLists.txt"
        if lists.is_file() and "project(scantrace" in lists.read_text(errors="replace"):
            return c
    where = given or "above this package"
    raise ZipError(f"--gradescope-zip: no scantrace source tree {where} (a folder with the "
                   "project's CMakeLists.txt): give --source DIR")


def _source_files(root):
    """The clone's tracked files (git ls-files), else every file but builds, .git and caches."""
    try:
        out = subprocess.run(["git", "-C", str(root), "ls-files", "-z"], capture_output=True,
                             check=True).stdout
        files = [f for f in out.decode().split("\0") if f and (root / f).is_file()]
        if files:
            return files
    except (OSError, subprocess.CalledProcessError):
        pass
    skip = {".git", "__pycache__", "node_modules"}
    files = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = [d for d in dirnames if d not in skip and not d.startswith("build")]
        files += [os.path.relpath(os.path.join(dirpath, f), root) for f in filenames]
    return sorted(files)


def _add_text(z, name, text, executable=False):
    info = zipfile.ZipInfo(name, date_time=(2024, 1, 1, 0, 0, 0))
    info.compress_type = zipfile.ZIP_DEFLATED
    mode = 0o755 if executable else 0o644
    info.external_attr = (stat.S_IFREG | mode) << 16
    z.writestr(info, text)


def grade_args(args, scene_name):
    """The options run_autograder passes to the grader, relative to /autograder/source."""
    out = []
    if args.hidden_seed is not None:
        out += ["--hidden-seed", str(args.hidden_seed)]
    if args.rubric:
        out += ["--rubric", "rubric.toml"]
    if scene_name:
        out += ["--scene", f"scene/{scene_name}"]
    if args.module:
        out += ["--module", args.module]
    if args.no_sandbox:
        out += ["--no-sandbox"]
    out += ["--call-seconds", repr(args.call_seconds), "--memory-mb", str(args.memory_mb)]
    return out


def write_zip(out_path, args):
    """Writes the autograder zip whole (a temp file renamed over OUT) and returns its file
    count. args: the grader's parsed options (rubric and scene already checked)."""
    out_path = pathlib.Path(out_path)
    if not out_path.parent.is_dir():
        raise ZipError(f"{out_path}: its folder {out_path.parent} does not exist")
    source = find_source(args.source)
    files = _source_files(source)
    scene_name = pathlib.Path(args.scene).name if args.scene else None
    fd, tmp = tempfile.mkstemp(dir=out_path.parent, prefix="." + out_path.name)
    os.close(fd)
    try:
        with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
            _add_text(z, "setup.sh", SETUP_SH.replace("@PACKAGES@", UBUNTU_PACKAGES)
                      .replace("@SANDBOX_CHECK@", SANDBOX_CHECK), True)
            _add_text(z, "run_autograder", RUN_AUTOGRADER, True)
            _add_text(z, "grade_args", "".join(a + "\n" for a in grade_args(args, scene_name)))
            if args.rubric:
                z.write(args.rubric, "rubric.toml")
            if scene_name:
                z.write(args.scene, f"scene/{scene_name}")
            for f in files:
                z.write(source / f, f"scantrace/{f}")
        os.chmod(tmp, 0o644)
        os.replace(tmp, out_path)
    except BaseException:
        os.unlink(tmp)
        raise
    return len(files)


def extract(zip_path, source_dir):
    """Unpacks the zip as Gradescope does (into /autograder/source), keeping the modes."""
    with zipfile.ZipFile(zip_path) as z:
        for info in z.infolist():
            path = z.extract(info, source_dir)
            mode = info.external_attr >> 16 & 0o777
            if mode:
                os.chmod(path, mode)
    return pathlib.Path(source_dir)

