"""What the grader writes: results.json in Gradescope's format (validated against a schema written
from Gradescope's documented fields), the reports, exit statuses, and the shapes of real
submissions it copes with (split files in a zip, nested lists of 0-255 values, new canvases)."""

import json
import os
import pathlib
import subprocess
import sys
import textwrap
import zipfile

import jsonschema
import pytest

from scantrace.grade import __main__ as cli

from conftest import CORRECT, grade_source, write_submission, wrong_source

SCHEMA = json.loads((pathlib.Path(cli.__file__).with_name("gradescope_results.schema.json"))
                    .read_text())


def test_results_json_is_gradescope_and_names_the_cause(tmp_path, sandbox_ok):
    graded = grade_source(tmp_path, wrong_source("right_end_excluded"))
    out = tmp_path / "student-out"
    text = (out / "results.json").read_text()
    assert len(text.encode()) <= 100_000
    results = json.loads(text)
    jsonschema.validate(results, SCHEMA)
    assert results["score"] == graded.score < graded.max_score
    assert [c["id"] for c in results["extra_data"]["causes"]] == ["right_end_excluded"]
    cause = results["extra_data"]["causes"][0]
    assert cause["picture"] == "causes/right_end_excluded.png"
    assert (out / cause["picture"]).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    hidden = [t for t in results["tests"] if t["name"].startswith("Hidden scene")]
    assert len(hidden) == 4 and {t["visibility"] for t in hidden} == {"after_published"}
    assert all(t["output_format"] == "md" for t in results["tests"])
    md = (out / "report.md").read_text()
    assert cause["sentence"] in md and "![right_end_excluded" in md and "expected columns" in md
    assert "data:image/png;base64," in (out / "report.html").read_text()


def test_schema_rejects_what_gradescope_would():
    bad = {"score": 1, "tests": [{"name": "t", "score": 1, "max_score": 1, "status": "ok"}]}
    try:
        jsonschema.validate(bad, SCHEMA)
    except jsonschema.ValidationError:
        return
    raise AssertionError("a status other than passed/failed was accepted")


def _run(*args):
    return subprocess.run([sys.executable, "-m", "scantrace.grade", *map(str, args)],
                          capture_output=True, text=True)


def test_usage_is_exit_2():
    assert _run().returncode == 2
    r = _run("x.py", "--jobs", "0")
    assert r.returncode == 2 and "--jobs" in r.stderr


def test_ungradeable_submission_is_exit_1_and_names_the_line(tmp_path, sandbox_ok):
    sub = write_submission(tmp_path / "broken", "def f_shading(img, v, c):\n    return img[\n")
    r = _run(sub, "-o", tmp_path / "out", "--quiet")
    assert r.returncode == 1
    assert "hw1.py:2: syntax error" in r.stderr
    results = json.loads((tmp_path / "out" / "results.json").read_text())
    jsonschema.validate(results, SCHEMA)
    assert results["score"] == 0 and results["output"].startswith("Not graded:")


def test_a_bad_rubric_is_named(tmp_path):
    rubric = tmp_path / "r.toml"
    rubric.write_text("[tests]\nprobes_flatt = 3\n")
    r = _run(tmp_path, "--rubric", rubric, "--no-sandbox")
    assert r.returncode == 2 and "r.toml: [tests] probes_flatt: no such key" in r.stderr


# A submission split over three files that import each other, zipped in a folder; its canvases
# are new nested lists of 0-255 values (render_img) or new arrays (the shading functions).
SPLIT = {
    "hw/interp.py": CORRECT.split("def _area2")[0].replace(
        "import matplotlib.pyplot as plt\nfrom tqdm import tqdm\n", ""),
    "hw/fill.py": "import math\nimport numpy as np\nfrom interp import vector_interp\n\n\ndef _area2"
                  + CORRECT.split("def _area2")[1].split("def render_img")[0].replace(
                      "        return _fill(img, vertices", "        return _fill(img.copy(), vertices"),
    "hw/main.py": textwrap.dedent('''\
        import numpy as np
        from fill import f_shading, g_shading
        from interp import vector_interp


        def render_img(faces, vertices, vcolors, depth, shading):
            img = np.ones((512, 512, 3))
            depth = np.asarray(depth, dtype=float).reshape(-1)
            for k in np.argsort(-depth[faces].mean(axis=1), kind="stable"):
                fill = f_shading if shading == "f" else g_shading
                img = fill(img, vertices[faces[k]], vcolors[faces[k]])
            return (np.round(img * 255)).astype(int).tolist()
        '''),
}


def test_split_zipped_submission_with_lists_scores_full(tmp_path, sandbox_ok):
    archive = tmp_path / "student7.zip"
    with zipfile.ZipFile(archive, "w") as z:
        for name, source in SPLIT.items():
            z.writestr(name, source)
        z.writestr("hw/README.txt", "not python")
    out = tmp_path / "out"
    assert cli.main([str(archive), "-o", str(out), "--quiet", "--hidden-seed", "3",
                     "--call-seconds", "3"]) == 0
    results = json.loads((out / "results.json").read_text())
    # Graded after the rescale; the 0–255 scale is named (with its deduction), nothing else.
    failed = [t["name"] for t in results["tests"] if t["status"] != "passed"]
    assert failed == ["Deduction: scaled_255"]
    assert [c["id"] for c in results["extra_data"]["causes"]] == ["scaled_255"]


def test_the_scantrace_command_forwards_to_the_grader(tmp_path):
    binary = os.environ.get("SCANTRACE_BINARY")
    if not binary:
        pytest.skip("SCANTRACE_BINARY is not set (CTest sets it)")
    r = subprocess.run([binary, "grade", "--help"], capture_output=True, text=True)
    assert r.returncode == 0 and "--hidden-seed" in r.stdout and "Gradescope" in r.stdout
    r = subprocess.run([binary, "grade"], capture_output=True, text=True)
    assert r.returncode == 2 and "SUBMISSION" in r.stderr
    r = subprocess.run([binary, "grade", str(tmp_path / "nothing.zip"), "-o", str(tmp_path),
                        "--no-sandbox"], capture_output=True, text=True)
    assert r.returncode == 1 and "nothing.zip: no such file or directory" in r.stderr
