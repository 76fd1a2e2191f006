"""The one mistake catalogue (issue 50): mistakes.json, read by the grader (causes.CATALOGUE),
embedded into the C++ diff at build time, and the ids the tests' wrong submissions are keyed by."""

import json
import pathlib
import re

from scantrace import _scantrace
from scantrace.grade import causes, diagnose, fill_models

from conftest import WRONG

GRADE_DIR = pathlib.Path(causes.__file__).resolve().parent


def test_the_cpp_diff_embeds_the_packages_file():
    package = json.loads((GRADE_DIR / "mistakes.json").read_text(encoding="utf-8"))
    assert json.loads(_scantrace.MISTAKE_CATALOGUE_JSON) == package


def test_catalogue_keeps_its_shape():
    assert isinstance(causes.CATALOGUE, dict)
    for cause_id, entry in causes.CATALOGUE.items():
        assert isinstance(entry, tuple) and len(entry) == 2, cause_id
        assert all(isinstance(t, str) and t for t in entry), cause_id
    c = causes.Cause("background", 1.0, "evidence", detail="(0.99, 0.99, 0.99)")
    assert c.sentence == "The background is (0.99, 0.99, 0.99) instead of white (1, 1, 1)."
    assert c.as_json()["fix"] == causes.CATALOGUE["background"][1]


def _named_in_grader_sources():
    """Every cause id the grader's code names: Cause("id", ...), the fill models' keys, the
    order alternatives' keys (read from the sources, independently of the catalogue)."""
    ids = {key for key, _ in fill_models.MODELS}
    for path in GRADE_DIR.glob("*.py"):
        text = path.read_text(encoding="utf-8")
        ids |= set(re.findall(r'Cause\(\s*"(\w+)"', text))
        ids |= set(re.findall(r'"(order_\w+)": \w+', text))
    # The whole-image mistakes are named by the C++ detector (whole_image.py) by these ids.
    return ids | set(diagnose.WHOLE_IMAGE_MISTAKES)


def test_every_cause_the_grader_names_is_in_the_catalogue():
    named = _named_in_grader_sources()
    assert {"order_reversed", "span_too_wide", "background"} <= named
    assert named - set(causes.CATALOGUE) == set()


def test_every_wrong_submission_is_keyed_by_a_catalogue_id():
    assert set(WRONG) - set(causes.CATALOGUE) == set()


def test_verdicts_in_the_issues_words():
    assert causes.VERDICTS["span_too_wide"] == \
        "spans are one pixel too wide on both sides (floor(x_L) .. ceil(x_R)?)"
    assert causes.VERDICTS["order_reversed"] == "faces are painted nearest first"
    assert causes.WHOLE_IMAGE["transform_gain"] == 2.0
