#!/usr/bin/env python3
"""Every command in README.md and docs/*.md runs as written (issue 20, point 7).

The commands are the lines of the fenced code blocks (```bash, ```sh or unlabelled) that start
with a program: build/cli/scantrace, scantrace, bash, cmake, python3, PYTHONPATH=..., echo, or
`$ ` followed by one. Each is

  * a synopsis (placeholders such as SCENE, OUT.png, [optional parts], a|b): its subcommand's
    --help must exit 0 and name every --option the synopsis names;
  * or listed in RUN below, with the files and the lines on stdout/stderr it promises: it is run
    through the shell in a scratch directory laid out like a fresh clone (build/cli/scantrace,
    examples/, docs/ and scripts/ of the source; `scantrace` on PATH, as after `cmake --install`;
    ../shared/data when this machine has it), after the demo the README's first command makes
    (`scantrace demo`, what scripts/demo.sh runs once it has built);
  * or listed in NOT_RUN with the reason (minutes long, builds or installs, needs a display).

A command in the docs that is in neither list fails the test (add it), and so does an entry of
the lists that the docs no longer hold (remove it). Commands reading ../shared/data are only run
with --course (a separate CTest test that reports SKIPPED, exit 77, when the data is missing).

usage: doc_commands.py SOURCE_DIR SCANTRACE_BINARY WORK_DIR [--course]
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import time
from pathlib import Path

SKIPPED = 77

# command (as written, without a trailing comment) -> what it must do.
#   exit: expected status (default 0); files: paths that must exist afterwards (relative to the
#   scratch directory; a trailing / is a non-empty directory); out / err: text that must appear.
RUN = {
    # README.md, docs/usage.md
    "build/cli/scantrace render scantrace-demo/demo_scene.json": {"files": ["demo_scene.png"]},
    "build/cli/scantrace render scantrace-demo/demo_scene.json --shading flat -o flat.png": {
        "files": ["flat.png"]},
    "build/cli/scantrace render scantrace-demo/demo_scene.json --fill-rule closed --subpixel-bits 0": {
        "files": ["demo_scene.png"]},
    "build/cli/scantrace render head.obj --light 0,0,-1 --shading gouraud --cull back --gamma 2.2 --depth zbuffer -o head.png": {
        "files": ["head.png"], "course": True},
    'build/cli/scantrace trace --triangle "20,20 250,80 300,400" -o triangle.jsonl': {
        "files": ["triangle.jsonl"]},
    "build/cli/scantrace trace scantrace-demo/demo_scene.json --triangles 40 --level pixel -o face40.jsonl": {
        "files": ["face40.jsonl"]},
    'build/cli/scantrace explain --triangle "20,20 250,80 300,400" -o triangle.mp4': {
        "files": ["triangle.mp4"]},
    "build/cli/scantrace replay triangle.jsonl -o frames/ --steps 5:12 --video-size 1920x1080": {
        # the frames are numbered as the steps (docs/usage.md "Outputs")
        "files": ["frames/frame_00005.png", "frames/frame_00012.png"],
        "absent": ["frames/frame_00001.png", "frames/frame_00013.png"]},
    # the display list's SVG backend: one file a step, or one step
    "build/cli/scantrace replay triangle.jsonl -o svg-frames/ --format svg": {
        "files": ["svg-frames/frame_00001.svg", "svg-frames/frame_00047.svg"],
        "absent": ["svg-frames/frame_00001.png"]},
    "build/cli/scantrace replay triangle.jsonl -o step11.svg --steps 11": {
        "files": ["step11.svg"], "err": ["step 11 of 47"]},
    'build/cli/scantrace explain --triangle "2.3,1.2 13,4.5 5,11.6" --size 16x14 -o small.mp4': {
        "files": ["small.mp4"]},
    "build/cli/scantrace explain scantrace-demo/demo_scene.json -o painter.mp4": {
        "files": ["painter.mp4"]},
    "build/cli/scantrace explain scantrace-demo/demo_scene.json --triangles 40 -o face40.mp4": {
        "files": ["face40.mp4"]},
    'build/cli/scantrace explain --triangle "20,20 250,80 300,400" -o triangle.html': {
        "files": ["triangle.html"]},
    "build/cli/scantrace replay scantrace-demo/triangle.jsonl -o triangle.html": {
        "files": ["triangle.html"]},
    "build/cli/scantrace stress --seconds 3 --seed 1": {"err": ["seed 1"]},
    "build/cli/scantrace stress --seed 7 --family huge --case 12 --method exact": {},
    'PYTHONPATH=build/python python3 -c "import scantrace; help(scantrace)"': {
        "out": ["render_img"], "python": True},
    # docs/models.md
    "scantrace render head.obj --light 0,0,-1 --shading gouraud --cull back --gamma 2.2 --depth zbuffer -o head.png": {
        "files": ["head.png"], "course": True},
    "scantrace render head.obj --model-colors random --unlit --shading flat": {
        "files": ["head.png"], "course": True},
    "scantrace render head.obj --eye 1,0.5,3 --fov 45": {"files": ["head.png"], "course": True},
    "scantrace trace head.obj --level pixel --rows 200:201 -o head.jsonl": {
        "files": ["head.jsonl"], "course": True},
    "scantrace explain examples/models/interpenetrating.obj --unlit -o why.mp4": {
        "files": ["why.mp4"]},
    # docs/grading.md
    "python3 docs/grading/student_render.py ../shared/data/hw1_2024.json student.npy": {
        "files": ["student.npy"], "course": True},
    "build/cli/scantrace diff ../shared/data/hw1_2024.json student.npy --shading flat -o graded/": {
        "exit": 3, "files": ["graded/diff.png", "graded/report.json"], "course": True},
    "scantrace why ../shared/data/hw1_2024.json 279 23 --shading flat": {
        "out": ["final colour (0.0706, 0.0667, 0.0497), written by face 415"], "course": True},
    "build/cli/scantrace grade docs/grading/student_hw1.py -o graded-hw1 --hidden-seed 2024": {
        "files": ["graded-hw1/results.json", "graded-hw1/report.md", "graded-hw1/report.html",
                  "graded-hw1/causes/right_end_excluded.png"],
        "out": ["right_end_excluded: ", "order_unstable_on_ties: "]},
}

NOT_RUN = {
    "bash scripts/build.sh --web": "builds (the web build; its tests are the web-labelled ones)",
    "scantrace explore -o explorer.html":
        "needs the web build; the test 'web: scantrace explore writes the explorer page' runs it",
    "bash scripts/demo.sh": "builds (build.sh --demo reconfigures build/); its run is the set-up here",
    "bash scripts/test.sh": "builds and runs this very suite",
    "build/cli/scantrace stress --seconds 600": "ten minutes",
    "build/cli/scantrace stress --seconds 300 --seed 20261121": "five minutes",
    "build/cli/scantrace stress --family slivers,meshes --method exact --method float":
        "runs the default 60 seconds",
    "build/cli/scantrace bench --scene ../shared/data/hw1_2024.json -o bench":
        "minutes; tests/cli/bench_command_test.cpp runs --quick",
    "build/bench/bench_kernels": "a benchmark (minutes)",
    "build/bench/bench_render": "a benchmark (minutes)",
    "bash scripts/bench_tracer_overhead.sh": "builds twice and times",
    "bash scripts/bench_tracer_overhead.sh 8": "builds twice and times",
    "bash scripts/model_images.sh": "regenerates committed images in the source tree",
    "cmake --install build --prefix ~/.local": "installs into the home directory; "
        "the install test installs into a temporary prefix",
    "/usr/bin/python3 -m venv --system-site-packages ~/venvs/scantrace": "makes a venv in the "
        "home directory; python/tests/test_setup_interpreter.py runs it into a temporary one "
        "with another python3 first on PATH, python/tests/test_install.py installs a wheel into "
        "a fresh venv",
    "build/cli/scantrace step scantrace-demo/triangle.jsonl": "a window: tests/interactive",
    'build/cli/scantrace step --triangle "20,20 250,80 300,400"': "a window: tests/interactive",
    "echo $?": "prints the previous command's status, which RUN checks",
    "scantrace grade subs/* -o class-out --jobs 2 --hidden-seed 2024": "needs a folder of "
        "submissions; python/tests/grade/test_grade_class.py grades a generated class of 30",
    "PYTHONPATH=build/python python3 -c 'import resource, sys; from scantrace.grade.__main__ "
    "import main; main(sys.argv[1:]); r = resource.getrusage(resource.RUSAGE_SELF); "
    "print(f\"grader CPU {r.ru_utime + r.ru_stime:.2f} s\")' docs/grading/student_hw1.py -o "
    "graded-hw1 --hidden-seed 2024 --quiet": "a measurement (its figures are in the table "
    "below it); the grade command above runs the same grading",
}

PROGRAMS = ("build/cli/scantrace", "scantrace", "bash", "cmake", "python3", "/usr/bin/python3",
            "PYTHONPATH=",
            "echo", "build/bench/")


def strip_comment(line):
    """The command without a trailing `# comment` (a # outside quotes after a space)."""
    quote = None
    for i, c in enumerate(line):
        if quote:
            if c == quote:
                quote = None
        elif c in "\"'":
            quote = c
        elif c == "#" and (i == 0 or line[i - 1] == " "):
            return line[:i].rstrip()
    return line.rstrip()


def doc_commands(source):
    """(file:line, command) for every command line of a fenced block; continuation lines (more
    indented, not a program) are joined to the command before them."""
    files = [source / "README.md"] + sorted((source / "docs").glob("*.md"))
    found = []
    for f in files:
        lines = f.read_text(encoding="utf-8").split("\n")
        in_block, runnable = False, False
        for n, line in enumerate(lines, 1):
            fence = re.match(r"^```(\w*)", line)
            if fence:
                in_block = not in_block
                runnable = in_block and fence.group(1) in ("bash", "sh", "")
                continue
            if not runnable:
                continue
            text = line[2:] if line.startswith("$ ") else line
            if text.startswith(PROGRAMS):
                found.append([f"{f.relative_to(source)}:{n}", strip_comment(text)])
            elif text.startswith(" ") and found and found[-1][0].startswith(
                    f"{f.relative_to(source)}:") and text.strip().startswith(("[", "|", "-")):
                found[-1][1] += " " + strip_comment(text.strip())
    return [(where, " ".join(cmd.split())) for where, cmd in found]


PLACEHOLDER = re.compile(r"(\[|\||…|\b(SCENE|TRACE|OUT|IMAGE|DIR|PREFIX|FILE|SECONDS|WxH|X Y)\b)")


def is_synopsis(cmd):
    return bool(PLACEHOLDER.search(cmd)) and ("scantrace " in cmd)


def check_synopsis(where, cmd, binary):
    words = cmd.split()
    sub = words[1]
    help_run = subprocess.run([binary, sub, "--help"], capture_output=True, text=True)
    problems = []
    if help_run.returncode != 0:
        problems.append(f"{where}: `scantrace {sub} --help` exits {help_run.returncode}")
    for option in sorted(set(re.findall(r"--[a-z][a-z-]*", cmd))):
        if option not in help_run.stdout:
            problems.append(f"{where}: the synopsis names {option}, `scantrace {sub} --help` does not")
    return problems


def set_up(source, binary, work, course):
    if work.exists():
        shutil.rmtree(work)
    clone = work / "clone"
    (clone / "build" / "cli").mkdir(parents=True)
    (work / "bin").mkdir()
    os.symlink(binary, clone / "build" / "cli" / "scantrace")
    os.symlink(binary, work / "bin" / "scantrace")
    # `python3` is the interpreter running this test: Debian's, whose numpy scripts/deps.sh
    # installs (the README says so), not whichever python3 comes first on the caller's PATH.
    os.symlink(sys.executable, work / "bin" / "python3")
    python_build = Path(binary).parent.parent / "python"
    if python_build.is_dir():
        os.symlink(python_build, clone / "build" / "python")
    for folder in ("examples", "docs", "scripts"):
        os.symlink(source / folder, clone / folder)
    shared = source.parent / "shared" / "data"
    if course:
        os.symlink(source.parent / "shared", work / "shared")
        # docs/models.md's head.obj is the course's model (see there)
        shutil.copy(shared / "african_head.obj", clone / "head.obj")
    demo = subprocess.run([str(clone / "build/cli/scantrace"), "-q", "demo"], cwd=clone,
                          capture_output=True, text=True)
    if demo.returncode != 0 or not (clone / "scantrace-demo" / "triangle.jsonl").exists():
        sys.exit(f"set-up: `scantrace demo` failed ({demo.returncode}): {demo.stderr}")
    return clone


def run(cmd, spec, clone, work):
    env = dict(os.environ, PATH=f"{work / 'bin'}:{os.environ.get('PATH', '')}")
    for f in spec.get("files", []) + spec.get("absent", []):
        target = clone / f
        if target.is_dir():
            shutil.rmtree(target)
        elif target.exists():
            target.unlink()
    r = subprocess.run(["sh", "-c", cmd], cwd=clone, env=env, capture_output=True, text=True,
                       timeout=900)
    problems = []
    want = spec.get("exit", 0)
    if r.returncode != want:
        problems.append(f"exit {r.returncode}, the docs promise {want}: {r.stderr.strip()[-400:]}")
    for f in spec.get("files", []):
        target = clone / f
        if not target.exists() or (target.is_file() and target.stat().st_size == 0):
            problems.append(f"no {f}")
    for f in spec.get("absent", []):
        if (clone / f).exists():
            problems.append(f"{f} should not have been written")
    for text in spec.get("out", []):
        if text not in r.stdout:
            problems.append(f"stdout lacks {text!r}")
    for text in spec.get("err", []):
        if text not in r.stderr:
            problems.append(f"stderr lacks {text!r}")
    return problems


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    course = "--course" in sys.argv
    if len(args) != 3:
        sys.exit(__doc__)
    source, binary, work = Path(args[0]).resolve(), args[1], Path(args[2])
    if course and not (source.parent / "shared" / "data" / "hw1_2024.json").exists():
        print(f"skipped: {source.parent / 'shared' / 'data'} is missing (the course scene)")
        return SKIPPED
    commands = doc_commands(source)
    problems, ran = [], 0
    listed = set()
    for where, cmd in commands:
        if is_synopsis(cmd) and cmd not in RUN and cmd not in NOT_RUN:
            if not course:
                problems += check_synopsis(where, cmd, binary)
            continue
        listed.add(cmd)
        if cmd not in RUN and cmd not in NOT_RUN:
            problems.append(f"{where}: `{cmd}` is in neither list of tests/docs/doc_commands.py: "
                            "add it with what it promises")
    for cmd in list(RUN) + list(NOT_RUN):
        if cmd not in listed:
            problems.append(f"tests/docs/doc_commands.py lists `{cmd}`, which no doc holds any more")
    if problems:
        print("\n".join(problems))
        return 1
    clone = set_up(source, binary, work, course)
    for where, cmd in commands:
        spec = RUN.get(cmd)
        if spec is None or spec.get("course", False) != course:
            continue
        if spec.get("python") and not (clone / "build" / "python").exists():
            print(f"{where}: not run, the Python module is not built: {cmd}")
            continue
        start = time.monotonic()
        found = run(cmd, spec, clone, work)
        ran += 1
        print(f"{where}: {'ok' if not found else 'FAILED'} ({time.monotonic() - start:.1f} s): {cmd}")
        problems += [f"{where}: `{cmd}`: {p}" for p in found]
    print(f"{ran} commands run, {len(problems)} problems")
    if problems:
        print("\n".join(problems))
        return 1
    shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
