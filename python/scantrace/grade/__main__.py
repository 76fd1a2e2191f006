"""python3 -m scantrace.grade: the command line of the grader (also `scantrace grade`)."""

import argparse
import math
import pathlib
import signal
import sys
import threading
import traceback

from . import classmode, rubric as rubric_module, untrusted
from .grader import Options, course_arrays, grade
from .sandbox import Limits, sandbox_problem

DESCRIPTION = """\
Grades students' triangle-filling code (vector_interp, f_shading, g_shading, render_img): runs
their functions in a sandbox (bubblewrap: no network, read-only system, private /tmp, limits) on
probe triangles, vector_interp cases, hidden scenes and the course scene, and names each mistake
as a cause with its fix and evidence.

One SUBMISSION writes DIR/results.json (Gradescope's format), DIR/report.md and DIR/report.html;
several write DIR/NAME/... for each and DIR/class.csv, DIR/class.html. A SUBMISSION is a
directory of .py files, one .py file or a .zip.

--gradescope-zip OUT.zip (no SUBMISSION) writes a Gradescope autograder instead: setup.sh,
run_autograder, the project's source and the grading options given with it (--hidden-seed,
--rubric, --scene, --module, the limits), for Gradescope's Ubuntu 24.04 image.

Exit status: 0 every submission graded (whatever its score), 1 a submission could not be graded
at all (or the sandbox cannot run here), 2 usage (a bad option or rubric)."""


def _finite(text):
    """A float option's value: a finite number (argparse's float() takes nan and inf)."""
    value = float(text)
    if not math.isfinite(value) or value <= 0:
        raise argparse.ArgumentTypeError(f"expected a finite number > 0, got {text!r}")
    return value


def _parser():
    p = argparse.ArgumentParser(prog="scantrace grade", description=DESCRIPTION,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("submissions", nargs="*", metavar="SUBMISSION")
    p.add_argument("-o", "--output", default="grade-out", metavar="DIR",
                   help="where the reports go (default: grade-out)")
    p.add_argument("--jobs", type=int, default=1, metavar="INT",
                   help="submissions graded at once, each in its own sandbox (default 1)")
    p.add_argument("--rubric", metavar="R.toml",
                   help="the total, each test's weight and visibility, the causes' deductions "
                        "(default: the documented default rubric)")
    p.add_argument("--hidden-seed", type=int, metavar="INT",
                   help="generate the hidden scenes from this seed (never shown to the code)")
    p.add_argument("--scene", metavar="PATH",
                   help="the course scene (hw1.npy, a scene .json or .mat) for the course-scene "
                        "tests")
    p.add_argument("--module", metavar="NAME",
                   help="take every function from this module of the submission")
    p.add_argument("--no-sandbox", action="store_true",
                   help="run student code without bubblewrap (only for code you trust)")
    p.add_argument("--call-seconds", type=_finite, default=10.0, metavar="FLOAT",
                   help="wall-time limit of one call (default 10; a scene gets 6 times this)")
    p.add_argument("--memory-mb", type=int, default=2048, metavar="INT",
                   help="address-space limit of the student's process (default 2048)")
    p.add_argument("--quiet", action="store_true", help="no progress on stderr")
    p.add_argument("--gradescope-zip", metavar="OUT.zip",
                   help="write a Gradescope autograder (setup.sh, run_autograder, the source and "
                        "these options) instead of grading")
    p.add_argument("--source", metavar="DIR",
                   help="with --gradescope-zip: the scantrace clone to put in it (default: the "
                        "one this package was built from)")
    return p


def _gradescope_zip(args):
    """The autograder zip; its scene is checked here, where the instructor can fix it."""
    from . import gradescope
    try:
        if args.scene:
            import scantrace
            course_arrays(scantrace.load_scene(args.scene))
        count = gradescope.write_zip(args.gradescope_zip, args)
    except (ValueError, OSError) as e:
        print(f"scantrace grade: {e}", file=sys.stderr)
        return 1
    if not args.quiet:
        print(f"{args.gradescope_zip}: Gradescope autograder (setup.sh, run_autograder, "
              f"{count} source files); upload it with the Ubuntu 24.04 base image")
    return 0


def _terminated(signum, frame):
    # SIGTERM as an exception: every `finally` runs, so the temporary folders (the staged
    # submission, the session's inputs) are removed and the sandboxes killed, and class mode
    # stops its workers and still writes class.csv; exit status 143.
    signal.signal(signum, signal.SIG_DFL)   # a second SIGTERM ends the grader at once
    raise SystemExit(128 + signum)


def main(argv=None):
    args = _parser().parse_args(argv)
    if threading.current_thread() is not threading.main_thread():
        return _main(args)   # called from a thread (a test): only the main thread has signals
    previous = signal.signal(signal.SIGTERM, _terminated)
    try:
        return _main(args)
    finally:
        signal.signal(signal.SIGTERM, previous)


def _main(args):
    if bool(args.gradescope_zip) == bool(args.submissions):
        _parser().error("give SUBMISSION... to grade, or --gradescope-zip OUT.zip alone")
    if args.source and not args.gradescope_zip:
        _parser().error("--source goes with --gradescope-zip")
    if args.jobs < 1:
        _parser().error("--jobs: expected a number >= 1")
    if args.memory_mb < 64:
        _parser().error("--memory-mb: expected a number >= 64")
    try:
        rubric = rubric_module.load(args.rubric)
    except rubric_module.RubricError as e:    # a usage error, as a bad option is
        print(f"scantrace grade: {e}", file=sys.stderr)
        return 2
    if args.gradescope_zip:
        return _gradescope_zip(args)
    if not args.no_sandbox:
        problem = sandbox_problem()
        if problem:
            print(f"scantrace grade: refusing to run student code without a sandbox: {problem}. "
                  "Or pass --no-sandbox, for code you trust only (docs/grading.md says what it "
                  "leaves unprotected).", file=sys.stderr)
            return 1
    scene = None
    if args.scene:
        import scantrace
        try:
            scene = course_arrays(scantrace.load_scene(args.scene))
        except (ValueError, OSError) as e:
            print(f"scantrace grade: {e}", file=sys.stderr)
            return 1
    options = Options(rubric, scene, args.hidden_seed, args.module, not args.no_sandbox,
                      Limits(call_seconds=args.call_seconds, memory_mb=args.memory_mb))
    out = pathlib.Path(args.output)
    if len(args.submissions) == 1:
        try:
            graded = grade(args.submissions[0], out, options)
        except Exception as e:  # a bug of the grader: still a results.json saying so
            traceback.print_exc()
            classmode.not_graded(pathlib.Path(args.submissions[0]).name, out, f"grader error: {e}")
            return 1
        if graded.error:
            print(f"scantrace grade: {untrusted.terminal(graded.error)}", file=sys.stderr)
            return 1
        if not args.quiet:
            print(untrusted.terminal(f"{graded.name}: {graded.score:g} / {graded.max_score:g}"
                                     + "".join(f"\n  {c.id}: {c.sentence}"
                                               for c in graded.causes)
                                     + f"\nreport: {out / 'report.md'}"))
        return 0
    return classmode.run(args.submissions, out, options, args.jobs, progress=not args.quiet)


if __name__ == "__main__":
    sys.exit(main())
