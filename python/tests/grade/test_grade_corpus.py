"""The realistic corpus (issue 50, point 7): submissions written as the course's students write
them (corpus/NAME/, independently of conftest.CORRECT), each graded in the sandbox and held to
what corpus/expected.toml says a fair grader gives it: every expected cause named, nothing else
but the `allowed` ones, the score within its band (a correct fill: full marks, no cause).

The expectations are not lowered to today's grader: entries it gets wrong fail here until the
grader is fixed. The whole corpus is graded once per session, two submissions at a time (each
runs in its own sandboxed children), with the hidden scenes of a fixed seed; the entries marked
`course` also on the course scene when ../shared/data holds it. The table of docs/grading.md's
"Corpus" is printed at the end and its data written to $SCANTRACE_CORPUS_RESULTS (default: the
test's temporary directory) for corpus/table.py."""

import concurrent.futures
import functools
import importlib.util
import json
import os
import pathlib

import pytest

from scantrace.grade import rubric
from scantrace.grade.causes import CATALOGUE
from scantrace.grade.grader import Options, course_arrays, grade
from scantrace.grade.sandbox import Limits

from conftest import SHARED_DATA, SOURCE_DIR, quick_options

CORPUS = pathlib.Path(__file__).resolve().parent / "corpus"


def _load_table():
    """corpus/table.py (expected.toml and the Markdown table), loaded by path: the corpus folder
    is not put on sys.path, where its students' modules (hw1, render_img, ...) would be found."""
    spec = importlib.util.spec_from_file_location("corpus_table", CORPUS / "table.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


table = _load_table()

EXPECTED = table.load_expected()
COURSE_NPY = SHARED_DATA / "hw1_2024.npy"
HIDDEN_SEED = 2024
# The verdicts a sandboxed call can end in are causes too (issue 50, point 4).
VERDICTS = {"timeout", "memory", "forbidden", "crashed"}


@functools.cache
def _course_scene():
    import scantrace
    return course_arrays(scantrace.load_scene(str(COURSE_NPY)))


def _options(course):
    if not course:
        return quick_options(hidden_seed=HIDDEN_SEED)
    # The course scene is 10,000 faces of the student's pure Python: 6 x 5 s per call.
    return Options(rubric=rubric.load(), scene=_course_scene(), hidden_seed=HIDDEN_SEED,
                   limits=Limits(call_seconds=5.0, batch_seconds=240.0))


def _grade_one(name, out):
    course = EXPECTED[name].get("course", False) and COURSE_NPY.exists()
    try:
        graded = grade(CORPUS / name, out / name, _options(course))
    except Exception as e:  # the grader itself failed: recorded, and the entry fails
        return {"fraction": 0.0, "causes": [], "error": f"grader raised {e!r}", "course": course}
    fraction = graded.score / graded.max_score if graded.max_score else 0.0
    return {"fraction": fraction, "score": graded.score, "max_score": graded.max_score,
            "causes": [c.id for c in graded.causes], "verdicts": graded.verdicts,
            "error": graded.error, "course": course,
            "failed_tests": [f"{t.name}: {t.score:g}/{t.max_score:g}"
                             + (f" ({t.verdict})" if t.verdict else "")
                             for t in graded.tests if t.status == "failed"],
            "seconds": round(graded.seconds, 1)}


def _selected(session):
    """The entries the run's selected tests need (all of them for the table): `-k NAME` grades
    one submission, not the 35."""
    names = set()
    for item in session.items:
        if item.name.startswith("test_corpus_table"):
            return list(EXPECTED)
        params = getattr(item, "callspec", None)
        if params is not None and params.params.get("name") in EXPECTED:
            names.add(params.params["name"])
    return [n for n in EXPECTED if n in names]


@pytest.fixture(scope="module")
def results(request, tmp_path_factory, sandbox_ok):
    out = tmp_path_factory.mktemp("corpus")
    # Two at a time: the machine's two cores; each grade() waits on its sandboxed children.
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        futures = {name: pool.submit(_grade_one, name, out) for name in _selected(request.session)}
        got = {name: f.result() for name, f in futures.items()}
    path = pathlib.Path(os.environ.get("SCANTRACE_CORPUS_RESULTS", out / "corpus-results.json"))
    path.write_text(json.dumps(got, indent=1))
    return got


def test_the_corpus_is_as_the_issue_asks():
    assert len(EXPECTED) >= 30
    correct = [n for n, e in EXPECTED.items() if e.get("correct")]
    assert len(correct) >= 8
    for name, e in EXPECTED.items():
        assert (CORPUS / name).is_dir() and list((CORPUS / name).glob("*.py")), name
        assert 0 <= e["min"] <= e["max"] <= 1 and e["style"], name
        if e.get("correct"):
            assert e["causes"] == [] and e["min"] == 1.0, name
        elif name.startswith("w_"):
            assert e["min"] >= 0.5, name      # one usual mistake keeps at least half
        known = set(CATALOGUE) | VERDICTS
        unknown = set(e["causes"]) - known
        assert not unknown or e.get("new"), (name, unknown)
    assert not set(p.name for p in CORPUS.iterdir() if p.is_dir() and p.name != "__pycache__") \
        - set(EXPECTED)


@pytest.mark.parametrize("name", list(EXPECTED))
def test_corpus_submission(results, name):
    e, r = EXPECTED[name], results[name]
    assert not r["error"], f"{name}: not graded: {r['error']}"
    found = set(r["causes"])
    missing = set(e["causes"]) - found
    extra = found - set(e["causes"]) - set(e.get("allowed", []))
    assert not missing and not extra and e["min"] - 1e-9 <= r["fraction"] <= e["max"] + 1e-9, (
        f"{name}: score {100 * r['fraction']:.1f} % (band {100 * e['min']:g}–"
        f"{100 * e['max']:g} %), causes missing {sorted(missing)}, unexpected {sorted(extra)}; "
        f"failed tests: {r.get('failed_tests')}")


def test_corpus_table(results, capsys):
    """Prints docs/grading.md's corpus table with the measured scores, in the test log."""
    with capsys.disabled():
        print("\n" + table.markdown(EXPECTED, results))
    assert set(results) == set(EXPECTED)


def test_the_docs_show_the_corpus_table():
    """docs/grading.md's "Corpus" table is corpus/table.py's, from expected.toml as it is."""
    docs = (SOURCE_DIR / "docs" / "grading.md").read_text()
    assert table.markdown(EXPECTED) in docs
