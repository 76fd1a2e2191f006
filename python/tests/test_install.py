"""`cmake --install` puts a working package into a prefix's lib/python3/dist-packages."""

import os
import pathlib
import subprocess
import sys

import pytest


def test_install_into_a_temporary_prefix(tmp_path):
    build = os.environ.get("SCANTRACE_BUILD_DIR")
    if not build:
        pytest.skip("SCANTRACE_BUILD_DIR is not set (run through CTest)")
    prefix = tmp_path / "prefix"
    subprocess.run(["cmake", "--install", build, "--prefix", str(prefix), "--component",
                    "python"], check=True, capture_output=True)
    site = prefix / "lib" / "python3" / "dist-packages"
    files = sorted(p.name for p in (site / "scantrace").iterdir())
    assert "__init__.py" in files and any(f.startswith("_scantrace") for f in files)
    script = ("import scantrace, numpy as np; "
              "img = scantrace.render_img([[0, 1, 2]], [[1, 1], [40, 2], [3, 30]], np.eye(3), "
              "np.zeros(3), 'g'); print(scantrace.__file__, int((img != 1).any(axis=2).sum()))")
    env = {**os.environ, "PYTHONPATH": str(site)}
    out = subprocess.run([sys.executable, "-c", script], env=env, check=True,
                         capture_output=True, text=True, cwd=tmp_path).stdout.split()
    assert pathlib.Path(out[0]).is_relative_to(site)
    assert int(out[1]) > 500
