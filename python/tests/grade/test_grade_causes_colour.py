"""Colour, image and order mistakes (conftest.WRONG): each named exactly, with the points of the
default rubric (the mistakes the grader undoes to grade the rest cost their [causes] points)."""

import pytest

from scantrace.grade import rubric
from scantrace.grade.causes import CONFIDENCE

from conftest import SOURCE_DIR, grade_source, wrong_source

OTHER_CAUSES = ["flat_colour_not_mean", "gouraud_weights_permuted", "colours_paired_after_sort",
                "transposed", "bgr", "background", "order_reversed", "order_unstable_on_ties",
                "vector_interp_degenerate"]


@pytest.mark.parametrize("cause", OTHER_CAUSES)
def test_wrong_submission_is_named(tmp_path, sandbox_ok, cause):
    graded = grade_source(tmp_path, wrong_source(cause))
    assert [c.id for c in graded.causes] == [cause]
    assert graded.causes[0].confidence >= CONFIDENCE
    assert graded.score < graded.max_score
    # Each cause cites its probe with a picture (vector_interp's case is text only: no image).
    picture = tmp_path / "student-out" / "causes" / f"{cause}.png"
    assert picture.exists() == (cause != "vector_interp_degenerate")
    deduction = rubric.load().deduction(cause)
    if deduction:
        # Undone, the image is right: only the cause's points are lost.
        assert graded.score == graded.max_score - deduction
        assert [t.name for t in graded.tests if t.score < t.max_score] == [f"Deduction: {cause}"]


def test_permutation_is_named(tmp_path, sandbox_ok):
    graded = grade_source(tmp_path, wrong_source("gouraud_weights_permuted"))
    # The wrong submission takes vcolors[[1, 2, 0]]: vertex 0 gets the colour of vertex 1, …
    assert "vertex 0 gets the colour of vertex 1" in graded.causes[0].sentence
    assert "vertex 2 gets the colour of vertex 0" in graded.causes[0].sentence


def test_two_mistakes_are_both_named(tmp_path, sandbox_ok):
    # docs/grading.md's example: the span's last pixel left out *and* ties painted the wrong way
    # round. The fill mistake changes pixels all over the hidden scenes; the order is still
    # decided on the pixels the order alone changes.
    source = (SOURCE_DIR / "docs" / "grading" / "student_hw1.py").read_text()
    graded = grade_source(tmp_path, source)
    assert [c.id for c in graded.causes] == ["right_end_excluded", "order_unstable_on_ties"]
