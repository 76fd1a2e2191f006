"""Grades one submission: stage it, run the battery in the sandbox, score, diagnose, write the
reports. Never raises for what the student's code does; a submission that cannot be graded at all
(no functions, not a zip) still gets a results.json saying why."""

import dataclasses
import pathlib
import time

import numpy as np

from . import report, untrusted
from .battery import Battery, TestResult, course_arrays  # noqa: F401 - the grader's API
from .sandbox import Limits, Session
from .submission import SubmissionError, stage


@dataclasses.dataclass
class Graded:
    name: str
    tests: list
    causes: list
    notes: list
    seconds: float
    error: str = ""          # why the submission could not be graded at all

    @property
    def max_score(self):
        return round(sum(t.max_score for t in self.tests), 2)

    @property
    def score(self):
        return round(max(0.0, sum(t.score for t in self.tests)), 2)

    @property
    def verdicts(self):
        return sorted({t.verdict for t in self.tests
                       if t.verdict in ("timeout", "memory", "forbidden", "crashed")})

    def summary(self):
        if self.error:
            return "Not graded:\n" + untrusted.md_block(self.error)   # file names: student text
        causes = ", ".join(f"`{c.id}`" for c in self.causes) or "none"
        return f"Score {self.score:g} / {self.max_score:g}. Causes found: {causes}."


@dataclasses.dataclass
class Options:
    rubric: object
    scene: dict | None = None
    hidden_seed: int | None = None
    module: str | None = None
    sandbox: bool = True
    limits: Limits = dataclasses.field(default_factory=Limits)


def _deductions(causes, rubric):
    """A cause the grader undid to grade the rest costs the rubric's [causes] points, as a test of
    its own whose output shows the cause (Cause.test)."""
    tests = []
    for c in causes:
        points = rubric.deduction(c.id)
        if points:
            c.test = f"Deduction: {c.id}"
            tests.append(TestResult(c.test, 0.0, -points, f"{points:g} points taken off."))
    return tests


def grade(path, out_dir, options):
    start = time.monotonic()
    path = pathlib.Path(path)
    try:
        sub = stage(path, options.module)
    except SubmissionError as e:
        graded = Graded(path.stem, [], [], [], time.monotonic() - start, error=str(e))
        report.write(graded, out_dir)
        return graded
    try:
        session = Session(sub.root, sub.functions, options.limits, options.sandbox)
        try:
            battery = Battery(session, sub.functions, options.rubric, options.scene,
                              options.hidden_seed)
            battery.build()
            battery.drop_unweighted()
            results = session.run(battery.calls)
            tests = battery.grade(results)
            notes = list(sub.notes)
            if session.skipped_demo:
                notes.append("top-level demo code was not run (it failed on import): "
                             + ", ".join(session.skipped_demo))
            if session.import_status is not None and session.import_status.status != "ok":
                notes.append(f"importing the submission failed "
                             f"({session.import_status.status}): "
                             + report.student_text(session.import_status.detail))
            tests += _deductions(battery.causes, options.rubric)
        finally:
            session.close()
    finally:
        sub.close()
    graded = Graded(sub.name, tests, battery.causes, notes, time.monotonic() - start)
    report.write(graded, out_dir)
    return graded
