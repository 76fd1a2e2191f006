"""`scantrace grade --gradescope-zip OUT.zip`: the zip's run_autograder, run in a directory laid
out as Gradescope's /autograder (source, submission, results), grades a known submission into a
results.json that the schema accepts, with the score the rubric gives that submission."""

import json
import os
import pathlib
import subprocess
import sys
import zipfile

import jsonschema
import pytest

from scantrace.grade import __main__ as cli
from scantrace.grade import gradescope, rubric

from conftest import SOURCE_DIR, wrong_source

SCHEMA = json.loads((pathlib.Path(cli.__file__).with_name("gradescope_results.schema.json"))
                    .read_text())
PACKAGE = str(pathlib.Path(cli.__file__).resolve().parents[2])  # the folder holding scantrace/


def _zip(tmp_path, *options):
    out = tmp_path / "autograder.zip"
    r = subprocess.run([sys.executable, "-m", "scantrace.grade", "--gradescope-zip", str(out),
                        "--quiet", *options], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return out


def _layout(tmp_path, zip_path, source):
    root = tmp_path / "autograder"
    gradescope.extract(zip_path, root / "source")
    (root / "submission").mkdir(parents=True)
    (root / "submission" / "hw1.py").write_text(source)
    (root / "results").mkdir()
    return root


def _run_autograder(root, package=PACKAGE):
    env = dict(os.environ, SCANTRACE_AUTOGRADER_ROOT=str(root), SCANTRACE_PYTHONPATH=package)
    env.pop("PYTHONPATH", None)  # as on Gradescope: the package is found through the script only
    return subprocess.run(["bash", str(root / "source" / "run_autograder")], env=env,
                          capture_output=True, text=True, timeout=240)


def test_the_zip_holds_gradescopes_two_scripts_executable_and_the_options(tmp_path):
    custom = tmp_path / "r.toml"
    custom.write_text("[causes]\ntransposed = 7\n")
    out = _zip(tmp_path, "--hidden-seed", "5", "--rubric", custom, "--memory-mb", "1024")
    with zipfile.ZipFile(out) as z:
        modes = {i.filename: i.external_attr >> 16 & 0o777 for i in z.infolist()}
        assert modes["setup.sh"] == modes["run_autograder"] == 0o755
        assert z.read("rubric.toml") == custom.read_bytes()
        args = z.read("grade_args").decode().split("\n")
        assert args[:4] == ["--hidden-seed", "5", "--rubric", "rubric.toml"]
        assert "1024" in args and "--no-sandbox" not in args
        assert "scantrace/CMakeLists.txt" in modes
        assert "scantrace/python/scantrace/grade/harness.py" in modes
        assert not any(n.startswith("scantrace/build/") for n in modes)
        setup = z.read("setup.sh").decode()
    assert "bubblewrap" in setup and "--target _scantrace" in setup
    r = subprocess.run(["bash", "-n", "-c", setup])
    assert r.returncode == 0


def test_run_autograder_grades_the_submission_into_results_json(tmp_path, sandbox_ok):
    # The transposed student: everything right once img[x][y] is undone, so its score is the
    # rubric's total (whatever tests ran) less the rubric's deduction for `transposed`, here a
    # custom 7 points.
    custom = tmp_path / "r.toml"
    custom.write_text("[causes]\ntransposed = 7\n")
    out = _zip(tmp_path, "--hidden-seed", "5", "--rubric", custom, "--call-seconds", "4")
    root = _layout(tmp_path, out, wrong_source("transposed"))
    r = _run_autograder(root)
    assert r.returncode == 0, r.stderr
    results = json.loads((root / "results" / "results.json").read_text())
    jsonschema.validate(results, SCHEMA)
    maximum = rubric.load(custom).total
    assert results["extra_data"]["max_score"] == maximum == 100
    assert results["score"] == maximum - 7
    assert [c["id"] for c in results["extra_data"]["causes"]] == ["transposed"]


def test_run_autograder_writes_results_json_when_the_grader_cannot_start(tmp_path):
    out = _zip(tmp_path)
    root = _layout(tmp_path, out, "def f_shading(img, v, c):\n    return img\n")
    r = _run_autograder(root, package=str(tmp_path / "no-package-here"))
    assert r.returncode == 0
    results = json.loads((root / "results" / "results.json").read_text())
    jsonschema.validate(results, SCHEMA)
    assert results["score"] == 0
    assert "No module named scantrace" in results["output"]


def test_zip_errors_are_one_line_and_usage_is_exit_2(tmp_path):
    r = subprocess.run([sys.executable, "-m", "scantrace.grade", "--gradescope-zip",
                        str(tmp_path / "nowhere" / "a.zip")], capture_output=True, text=True)
    assert r.returncode == 1 and "nowhere" in r.stderr and "does not exist" in r.stderr
    assert not (tmp_path / "nowhere").exists()
    r = subprocess.run([sys.executable, "-m", "scantrace.grade", "sub.py", "--gradescope-zip",
                        str(tmp_path / "a.zip")], capture_output=True, text=True)
    assert r.returncode == 2 and "--gradescope-zip" in r.stderr
    r = subprocess.run([sys.executable, "-m", "scantrace.grade", "--gradescope-zip",
                        str(tmp_path / "a.zip"), "--source", str(tmp_path)],
                       capture_output=True, text=True)
    assert r.returncode == 1 and "no scantrace source tree" in r.stderr
    assert not (tmp_path / "a.zip").exists()


def test_setup_sh_installs_what_the_debian_build_installs_and_the_docs_list():
    """setup.sh's Ubuntu packages are names scripts/deps.sh installs on Debian (the build tested
    here), and docs/grading.md's Ubuntu check covers each of them once."""
    import re

    deps = (SOURCE_DIR / "scripts" / "deps.sh").read_text()
    debian = set()
    for group in re.findall(r"^\s*(?:demo_)?packages\+?=\(([^)]*)\)", deps, re.M | re.S):
        debian.update(w for w in group.split() if not w.startswith("#"))
    ubuntu = gradescope.UBUNTU_PACKAGES.split()
    assert len(ubuntu) == len(set(ubuntu))
    assert set(ubuntu) <= debian, set(ubuntu) - debian
    docs = (SOURCE_DIR / "docs" / "grading.md").read_text()
    section = docs[docs.index("### setup.sh's packages"):]
    table = section[section.index("| packages |"):section.index("\n\n", section.index("| packages |"))]
    named = {w for cell in re.findall(r"`([^`]*)`", table) for w in cell.split()}
    assert set(ubuntu) <= named, set(ubuntu) - named


@pytest.mark.parametrize("no_sandbox", [False, True])
def test_setup_sh_stops_at_image_build_when_the_sandbox_cannot_run(tmp_path, no_sandbox):
    """setup.sh's last step asks the built grader whether bwrap can make its namespaces (here a
    stub package that says it cannot) and fails the image's build with that reason, unless the zip
    was made with --no-sandbox."""
    grade = tmp_path / "build" / "python" / "scantrace" / "grade"
    grade.mkdir(parents=True)
    (grade.parent / "__init__.py").write_text("")
    (grade / "__init__.py").write_text("")
    (grade / "sandbox.py").write_text("def sandbox_problem():\n"
                                      "    return 'no user namespaces in this container'\n")
    (tmp_path / "grade_args").write_text("--hidden-seed\n5\n" + ("--no-sandbox\n" * no_sandbox))
    setup = gradescope.SETUP_SH.replace("@SANDBOX_CHECK@", gradescope.SANDBOX_CHECK)
    assert gradescope.SANDBOX_CHECK in setup
    r = subprocess.run(["bash", "-euo", "pipefail", "-c", gradescope.SANDBOX_CHECK],
                       cwd=tmp_path, capture_output=True, text=True)
    if no_sandbox:
        assert r.returncode == 0, r.stderr
    else:
        assert r.returncode == 1
        assert "no user namespaces in this container" in r.stderr and "--no-sandbox" in r.stderr
