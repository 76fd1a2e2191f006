"""Points follow how much is right (scoring.py, docs/grading.md "Scoring"): partial credit per
probe row and pixel checked against hand-counted masks; deliberately wrong submissions (conftest's
WRONG) keep what their mistake leaves right; the rubric's total is the maximum whatever ran, a test
weighted 0 is not run, tests can be hidden, unknown keys are a usage error; each cause's sentence,
fix and evidence are in the visible output of its test."""

import json
import re
import subprocess
import sys

import numpy as np
import pytest

from scantrace.grade import classmode, rubric
from scantrace.grade.grader import grade

from conftest import CORRECT, _line, grade_source, quick_options, write_submission, wrong_source

# ---- the credit of one probe, against counts made by hand ------------------------------------


def _mask(rows, width=8):
    """A mask from {row: (first, last)} spans, inclusive."""
    m = np.zeros((len(rows) + 2, width), bool)
    for y, (a, b) in rows.items():
        m[y, a:b + 1] = True
    return m


def test_a_flat_probe_is_credited_by_its_rows():
    from scantrace.grade import scoring
    expected = _mask({1: (2, 5), 2: (1, 5), 3: (1, 6), 4: (2, 4)})
    # Row 1 right, row 2 one pixel short on the right (near), row 3 missing, row 4 right, and a
    # row 5 drawn that should be empty: 5 rows count, 2 right, 1 near.
    got = _mask({1: (2, 5), 2: (1, 4), 4: (2, 4), 5: (3, 3)})
    assert scoring.fill_rows(expected, got) == (2, 1, 5)
    assert scoring.flat_probe(expected, got) == pytest.approx((2 + 0.5) / 5)
    assert scoring.flat_probe(expected, got, colour_ok=False) == pytest.approx(0.25)
    assert scoring.flat_probe(expected, expected) == 1.0
    assert scoring.flat_probe(expected, np.zeros_like(expected)) == 0.0   # a missing face
    # A row two pixels off, or broken in two, is wrong, not near.
    assert scoring.fill_rows(_mask({1: (2, 5)}), _mask({1: (2, 7)})) == (0, 0, 1)
    broken = _mask({1: (2, 5)})
    broken[1, 3] = False
    assert scoring.fill_rows(_mask({1: (2, 5)}), broken) == (0, 0, 1)


def test_a_gouraud_probe_is_credited_by_its_pixels():
    from scantrace.grade import scoring
    expected = np.zeros((10, 10), bool)
    expected[2:8, 2:8] = True                       # 36 pixels
    got = expected.copy()
    got[2, 2:5] = False                             # 3 pixels not filled
    colour_right = np.ones((10, 10), bool)
    # 3 pixels filled differently, colour exact elsewhere: 33 of 36 (the 0 of 20).
    assert scoring.gouraud_probe(expected, got, colour_right) == pytest.approx(33 / 36)
    colour_right[7, :] = False                      # 6 covered pixels with a wrong colour
    assert scoring.gouraud_probe(expected, got, colour_right) == pytest.approx((27 + 3) / 36)


def test_an_image_is_credited_on_the_pixels_a_face_covers():
    from scantrace.grade import scoring
    reference = np.ones((20, 20, 3))
    reference[5:15, 5:15] = 0.3                     # one face: 100 pixels
    student = reference.copy()
    student[5, 5:15] = 1.0                          # 10 of them left white
    student[0, 0:5] = 0.3                           # 5 drawn outside the face
    uncovered = (reference == 1).all(axis=2)
    credit, wrong, counted = scoring.image_credit(student, reference, uncovered)
    assert (wrong, counted) == (15, 105) and credit == pytest.approx(90 / 105)


def test_the_total_is_shared_out_exactly():
    from scantrace.grade import scoring
    from scantrace.grade.battery import TestResult
    tests = [TestResult(str(k), 0.0, weight=w, fraction=f)
             for k, (w, f) in enumerate([(5, 1), (5, 0.5), (20, 1), (20, 0), (10, 1)])]
    tests.append(TestResult("Deduction: bgr", 0.0, -5.0))
    scoring.allot(tests, 100)
    # 100 / 60 per weight: 8.333…, rounded by the largest remainder to add up to 100 exactly:
    # 16.666… rounds up, then of the four …33.33 the heavier first.
    assert [t.max_score for t in tests] == [8.33, 8.33, 33.34, 33.33, 16.67, 0.0]
    assert [t.score for t in tests] == [8.33, 4.17, 33.34, 0.0, 16.67, -5.0]


# ---- deliberately wrong submissions ----------------------------------------------------------

USUAL = ["span_end_rounding", "closed_rule", "bottom_row_dropped", "order_reversed",
         "transposed", "flat_colour_not_mean", "gouraud_weights_permuted"]
FILL = ("span_end_rounding", "closed_rule", "bottom_row_dropped")
COLOUR = {"flat_colour_not_mean": "Probes: flat", "gouraud_weights_permuted": "Probes: Gouraud"}
BACKGROUND_099 = _line("CANVAS", "img = np.full((512, 512, 3), 0.99)")(CORRECT)


@pytest.mark.parametrize("mistake", USUAL + ["background_0.99"])
def test_one_usual_mistake_keeps_at_least_half(tmp_path, sandbox_ok, mistake):
    source = BACKGROUND_099 if mistake == "background_0.99" else wrong_source(mistake)
    graded = grade_source(tmp_path, source)
    assert graded.max_score == 100
    assert 50 <= graded.score < 100, [(t.name, t.score, t.max_score) for t in graded.tests]
    if mistake in FILL:
        # A fill mistake leaves most of every probe right: each probe test keeps half its points
        # (all-or-nothing probes gave these 0 to 6 of 20).
        for t in graded.tests:
            if t.name.startswith("Probes"):
                assert t.score >= 0.5 * t.max_score, (t.name, t.score, t.output)
    if mistake in COLOUR:
        # A wrong colour on the right pixels keeps half of its probes' points (they were 2 and 0).
        t = next(t for t in graded.tests if t.name.startswith(COLOUR[mistake]))
        assert 0.5 * t.max_score <= t.score < t.max_score, (t.name, t.score, t.output)


def test_a_one_row_mistake_costs_less_than_a_reversed_order(tmp_path, sandbox_ok):
    one_row = grade_source(tmp_path, wrong_source("bottom_row_dropped"), name="a")
    reversed_order = grade_source(tmp_path, wrong_source("order_reversed"), name="b")
    assert one_row.score > reversed_order.score
    # A reversed order spoils every pixel the order decides: the pairs of distinct depths is
    # scored on its overlap, and loses all of it (the shared edge's pair is right, and so is the
    # tied pair: a stable ascending sort keeps ties in face order).
    pairs = next(t for t in reversed_order.tests if t.name.startswith("Probes: pairs"))
    assert pairs.score == pytest.approx(pairs.max_score * 2 / 3, abs=0.01), pairs.output
    assert ("pair `distinct_depths` (two overlapping faces, the farther drawn first, faces 4 "
            "and 5), credit 0%") in pairs.output
    # The dropped row leaves most of each probe right: the fill tests keep 80 % and more.
    for t in one_row.tests:
        if t.name.startswith(("Probes: flat", "Probes: Gouraud")):
            assert t.score >= 0.8 * t.max_score, (t.name, t.score)


def test_probes_with_non_integer_vertices_are_beyond_the_assignment(tmp_path, sandbox_ok):
    # Rounding the vertices first is harmless on the course's integer vertices: full marks by
    # default, the non-integer probes reported as not scored; a rubric may weight them.
    old = "    vertices = np.asarray(vertices, dtype=float)\n    if _area2(vertices) == 0:"
    assert CORRECT.count(old) == 1
    source = CORRECT.replace(old, old.replace("np.asarray(vertices, dtype=float)",
                                              "np.round(np.asarray(vertices, dtype=float))"))
    graded = grade_source(tmp_path, source, name="a")
    assert graded.score == graded.max_score == 100
    flat = next(t for t in graded.tests if t.name.startswith("Probes: flat"))
    assert "Beyond the assignment, not scored" in flat.output and "probe `halves`" in flat.output
    rubric_file = tmp_path / "r.toml"
    rubric_file.write_text("[tests]\nprobes_beyond = 10\n")
    options = quick_options()
    options.rubric = rubric.load(rubric_file)
    graded = grade(write_submission(tmp_path / "b", source), tmp_path / "b-out", options)
    beyond = next(t for t in graded.tests if t.key == "probes_beyond")
    assert beyond.score < beyond.max_score and graded.max_score == 100


# ---- the rubric ------------------------------------------------------------------------------


def _grade_cli(tmp_path, source, *options):
    sub = tmp_path / "sub"
    sub.mkdir(parents=True, exist_ok=True)
    (sub / "hw1.py").write_text(source)
    out = tmp_path / "out"
    r = subprocess.run([sys.executable, "-m", "scantrace.grade", str(sub), "-o", str(out),
                        "--quiet", "--call-seconds", "3", *map(str, options)],
                       capture_output=True, text=True)
    return r, (json.loads((out / "results.json").read_text()) if r.returncode == 0 else None)


def test_the_maximum_is_the_rubric_total_whatever_ran(tmp_path, sandbox_ok):
    r, without = _grade_cli(tmp_path / "a", wrong_source("right_end_excluded"))
    assert r.returncode == 0, r.stderr
    r, with_hidden = _grade_cli(tmp_path / "b", wrong_source("right_end_excluded"),
                                "--hidden-seed", 4)
    for results in (without, with_hidden):
        assert results["extra_data"]["max_score"] == 100
        assert round(sum(t["max_score"] for t in results["tests"]), 2) == 100
    assert len(with_hidden["tests"]) == len(without["tests"]) + 4


def test_weight_0_is_not_run_and_visibility_is_the_rubrics(tmp_path, sandbox_ok):
    rubric_file = tmp_path / "r.toml"
    rubric_file.write_text("[tests]\nprobes_gouraud = 0\n[visibility]\nprobes_pairs = 'hidden'\n")
    r, results = _grade_cli(tmp_path, wrong_source("gouraud_weights_permuted"),
                            "--rubric", rubric_file)
    assert r.returncode == 0, r.stderr
    names = [t["name"] for t in results["tests"]]
    assert not any("Gouraud" in n for n in names)
    assert results["extra_data"]["causes"] == []     # g_shading was never called
    assert results["score"] == results["extra_data"]["max_score"] == 100
    pairs = next(t for t in results["tests"] if t["name"].startswith("Probes: pairs"))
    assert pairs["visibility"] == "hidden"


@pytest.mark.parametrize("text", ["[causes]\nno_such_cause = 3\n", "[visibility]\nprobes = 'x'\n",
                                  "[visibility]\nprobes_flat = 'sometimes'\n",
                                  "[score]\nmaximum = 3\n", "[hidden]\nscenes = 1.5\n",
                                  "[extra]\na = 1\n", "[tests]\nprobes_flatt = 3\n"])
def test_unknown_rubric_keys_are_a_usage_error(tmp_path, text):
    rubric_file = tmp_path / "r.toml"
    rubric_file.write_text(text)
    r = subprocess.run([sys.executable, "-m", "scantrace.grade", str(tmp_path), "--rubric",
                        str(rubric_file), "--no-sandbox"], capture_output=True, text=True)
    assert r.returncode == 2 and "r.toml: " in r.stderr and "[" in r.stderr, r.stderr


# ---- what students see -----------------------------------------------------------------------


def test_each_cause_is_in_the_visible_output_of_its_test(tmp_path, sandbox_ok):
    r, results = _grade_cli(tmp_path, wrong_source("right_end_excluded"))
    assert r.returncode == 0, r.stderr
    cause = results["extra_data"]["causes"][0]
    showing = [t for t in results["tests"] if cause["sentence"] in t["output"]]
    assert len(showing) == 1 and showing[0]["visibility"] == "visible"
    assert showing[0]["score"] < showing[0]["max_score"]
    assert cause["fix"] in showing[0]["output"]
    # The evidence, built from the student's output, is shown literally (a code span).
    # A code span whose fence is longer than the evidence's own backtick runs (CommonMark: a
    # space inside each fence is optional when the text does not start or end with a backtick).
    fence = "`" * 2
    assert re.search(re.escape(fence) + " ?" + re.escape(cause["evidence"]) + " ?" + re.escape(fence),
                     showing[0]["output"])
    assert [t["number"] for t in results["tests"]] == ["1.1", "1.2", "2.1", "2.2", "2.3"]


def test_a_crash_text_is_fenced_in_the_output(tmp_path, sandbox_ok):
    source = CORRECT.replace("def vector_interp(p1, p2, V1, V2, coord, dim):\n",
                             "def vector_interp(p1, p2, V1, V2, coord, dim):\n"
                             "    raise ValueError('*bold* <b>x</b> [link](http://e.org)')\n")
    r, results = _grade_cli(tmp_path, source)
    assert r.returncode == 0, r.stderr
    output = results["tests"][0]["output"]
    text = "*bold* <b>x</b> [link](http://e.org)"
    # Every occurrence of the student's text lies inside a code span or fence.
    for k in [i for i in range(len(output)) if output.startswith(text, i)]:
        before = output[:k]
        assert before.count("`") % 2 == 1 or before.count("```") % 2 == 1, output


def test_an_ungradeable_submission_says_so(tmp_path):
    sub = tmp_path / "sub"
    sub.mkdir()
    (sub / "hw1.py").write_text("def render_img(:\n")
    subprocess.run([sys.executable, "-m", "scantrace.grade", str(sub), "-o",
                    str(tmp_path / "out"), "--quiet", "--no-sandbox"], capture_output=True)
    md = (tmp_path / "out" / "report.md").read_text()
    assert "not graded" in md.splitlines()[0] and "hw1.py:1" in md and "0 / 0" not in md


def test_class_html_flags_a_low_score_without_a_cause():
    row = {"score": 20.0, "max_score": 100.0, "verdicts": "", "error": "",
           "tests": [("Probes: flat fill", 2.0, 20.0), ("vector_interp: ordinary cases", 5, 5)]}
    rows = [dict(row, name="quiet", causes=""), dict(row, name="student_b", causes="bgr")]
    page = classmode.class_html(rows)
    flagged = page[page.index("Low score, no cause"):]
    flagged = flagged[:flagged.index("<h2>", 5)]
    assert "quiet" in flagged and "student_b" not in flagged
    assert "2/20" in page and "title='Probes: flat fill'" in page


def test_weight_0_makes_no_call(tmp_path):
    """The calls of a test weighted 0 are never made: the Gouraud probes' g_shading calls and
    the hidden scenes' render_img calls are left out of the batch sent to the sandbox."""
    from types import SimpleNamespace

    from scantrace.grade.battery import Battery
    rubric_file = tmp_path / "r.toml"
    rubric_file.write_text("[tests]\nprobes_gouraud = 0\nhidden_scene = 0\n")
    session = SimpleNamespace(input=lambda array: "npy", limits=SimpleNamespace(call_seconds=1))
    functions = {"vector_interp": 1, "f_shading": 1, "g_shading": 1, "render_img": 1}
    battery = Battery(session, functions, rubric.load(rubric_file), hidden_seed=3)
    battery.build()
    assert any(c["func"] == "g_shading" for c in battery.calls)      # built, then left out
    battery.drop_unweighted()
    assert not any(c["func"] == "g_shading" for c in battery.calls)
    assert not any(c["id"].startswith("hidden") for c in battery.calls) and not battery.hidden
    assert any(c["func"] == "f_shading" for c in battery.calls)
