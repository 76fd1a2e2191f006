"""A class of 30 generated submissions graded with --jobs 2: class.csv equals the per-submission
results.json files, class.html counts the causes, and one ungradeable submission makes exit 1."""

import csv
import json

from scantrace.grade import __main__ as cli

from conftest import CORRECT, WRONG, write_submission, wrong_source


def test_class_csv_equals_the_reports(tmp_path, sandbox_ok):
    causes = sorted(WRONG)
    paths = []
    for k in range(30):
        source = CORRECT if k % 3 == 0 else wrong_source(causes[k % len(causes)])
        if k == 29:
            source = "def render_img(:\n"        # cannot be graded at all
        paths.append(write_submission(tmp_path / "class" / f"student{k:02d}", source))
    out = tmp_path / "out"
    status = cli.main([*map(str, paths), "-o", str(out), "--jobs", "2", "--quiet",
                       "--call-seconds", "3"])
    assert status == 1   # student29 could not be graded
    with open(out / "class.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert [r["name"] for r in rows] == [p.name for p in paths]
    for row in rows:
        results = json.loads((out / row["name"] / "results.json").read_text())
        assert float(row["score"]) == results["score"]
        assert row["causes"].split() == [c["id"] for c in results["extra_data"]["causes"]]
        verdicts = {t.get("extra_data", {}).get("verdict") for t in results["tests"]}
        assert set(row["verdicts"].split()) == verdicts & {"timeout", "memory", "forbidden",
                                                          "crashed"}
        if row["name"] == "student29":
            assert row["error"] and results["output"].startswith("Not graded")
        else:
            assert row["error"] == ""
            # No hidden scene: the rubric's total all the same, shared over the tests that ran.
            assert float(row["max_score"]) == results["extra_data"]["max_score"] == 100
    # Every third student is correct; the others each carry the one cause written into them.
    for k, row in enumerate(rows[:29]):
        expected = [] if k % 3 == 0 else [causes[k % len(causes)]]
        # (render_img's mistakes — bgr, background, the painter's order — show on the pairs
        # probe even with no hidden scene.)
        assert row["causes"].split() == expected, row
    page = (out / "class.html").read_text()
    assert "30 submissions" in page and "student29" in page
