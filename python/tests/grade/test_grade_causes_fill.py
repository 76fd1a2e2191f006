"""Each deliberately wrong fill (conftest.WRONG, written in the course's style) is graded and the
report names exactly its cause; the correct submission scores full marks with no cause. The fill
models themselves are checked against the C++ fill and against each other."""

import itertools

import numpy as np
import pytest

import scantrace
from scantrace.grade import fill_models
from scantrace.grade.causes import CONFIDENCE
from scantrace.grade.probes import PROBES

from conftest import CORRECT, grade_source, wrong_source

FILL_CAUSES = ["span_end_rounding", "right_end_excluded", "closed_rule", "span_too_wide",
               "top_row_dropped", "bottom_row_dropped", "edge_lag", "float_drift",
               "degenerate_drawn", "horizontal_edge_skipped"]


def test_the_correct_model_is_the_cpp_fill():
    rng = np.random.default_rng(5)
    for k in range(200):
        v = rng.integers(-3, 30, (3, 2)).astype(float)
        if k % 2:
            v = np.round(rng.uniform(-3, 30, (3, 2)) * 4) / 4
        img = scantrace.f_shading(np.ones((28, 28, 3)), v, np.full((3, 3), 0.3))
        assert (np.any(img != 1, axis=2) == fill_models.correct(v, (28, 28))).all(), v


def test_every_two_fill_models_differ_on_some_probe():
    models = dict(fill_models.MODELS, correct=fill_models.correct)
    for a, b in itertools.combinations(models, 2):
        differ = sum(int((models[a](p.array, p.size) != models[b](p.array, p.size)).sum())
                     for p in PROBES)
        assert differ > 0, (a, b)


def test_correct_submission_full_marks_no_cause(tmp_path, sandbox_ok):
    graded = grade_source(tmp_path, CORRECT)
    assert graded.causes == []
    assert graded.score == graded.max_score == 100   # default rubric: 5+5+20+20+10+4*10
    assert all(t.status == "passed" for t in graded.tests)
    # The demo at the bottom (a hard-coded path, a window) was skipped, and said so.
    assert any("hw1.py:" in n and "demo" in n for n in graded.notes)


@pytest.mark.parametrize("cause", FILL_CAUSES)
def test_wrong_fill_is_named(tmp_path, sandbox_ok, cause):
    graded = grade_source(tmp_path, wrong_source(cause))
    assert [c.id for c in graded.causes] == [cause]
    c = graded.causes[0]
    assert c.confidence >= CONFIDENCE
    assert "probe `" in c.evidence and "row " in c.evidence and "expected columns" in c.evidence
    assert (tmp_path / "student-out" / "causes" / f"{cause}.png").exists()
    assert graded.score < graded.max_score
