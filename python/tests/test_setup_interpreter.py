"""The README's Python commands from a shell whose `python3` is not Debian's (pyenv, conda): a
venv of Debian's interpreter made without its site packages stands in for one (no numpy, no
setuptools, no wheel, no pip; no package index here). `setup.py` run by it fails at once with the
commands that work, which are the README's; the README's venv command, run with it first on
PATH, still gives an interpreter with numpy."""

import os
import re
import subprocess
import sys
import time

import pytest

from conftest import SOURCE_DIR


def readme_commands():
    text = (SOURCE_DIR / "README.md").read_text(encoding="utf-8")
    block = re.search(r"## From Python\s+```\n(.*?)```", text, re.S).group(1)
    return [line.split("#")[0].strip() for line in block.splitlines() if line.strip()]


@pytest.fixture(scope="module")
def fake_pyenv(tmp_path_factory):
    root = tmp_path_factory.mktemp("fakepyenv")
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(root)], check=True)
    probe = subprocess.run([str(root / "bin" / "python3"), "-c", "import numpy"],
                           capture_output=True)
    assert probe.returncode != 0  # the stand-in has no numpy
    return root


def test_setup_py_of_an_interpreter_without_numpy_fails_at_once(fake_pyenv):
    start = time.monotonic()
    r = subprocess.run([str(fake_pyenv / "bin" / "python3"), "setup.py", "--name"],
                       cwd=SOURCE_DIR, capture_output=True, text=True, timeout=60)
    assert r.returncode != 0
    assert time.monotonic() - start < 10  # at once: no CMake, no compile
    assert "Traceback" not in r.stderr
    assert "has no setuptools, wheel, numpy" in r.stderr
    for command in readme_commands():  # the way out it names is the README's
        assert command in r.stderr
    assert "plain `pip install .`" in r.stderr


def test_the_readmes_venv_has_numpy_with_another_python3_first_on_path(fake_pyenv, tmp_path):
    venv_command = readme_commands()[0].replace("~/venvs/scantrace", str(tmp_path / "venv"))
    env = dict(os.environ, PATH=f"{fake_pyenv / 'bin'}{os.pathsep}{os.environ['PATH']}")
    subprocess.run(["bash", "-c", venv_command], env=env, check=True)
    r = subprocess.run([str(tmp_path / "venv" / "bin" / "python"), "-c",
                        "import numpy, setuptools, wheel"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
