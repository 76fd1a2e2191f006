"""`cmake --install` puts a working package into a prefix's lib/python3/dist-packages."""

import os
import pathlib
import shutil
import subprocess
import sys
import textwrap

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


def source_files(root):
    """Every file of the clone outside its build directories (what an install must not touch)."""
    out = set()
    for d, dirs, files in os.walk(root):
        rel = pathlib.Path(d).relative_to(root)
        dirs[:] = [x for x in dirs if not (rel == pathlib.Path(".") and
                                           (x.startswith("build") or x == ".git"))
                   and x != "__pycache__"]
        out.update(str(rel / f) for f in files)
    return out


def test_wheel_installs_into_a_fresh_venv_and_imports_elsewhere(tmp_path):
    """`python3 -m build --wheel --no-isolation` (setup.py driving this build's CMake), then the
    wheel into a fresh `venv --system-site-packages`, imported from a directory outside the clone:
    it renders, answers why/diff, loads no OpenCV, and names what explain() is missing."""
    build = os.environ.get("SCANTRACE_BUILD_DIR")
    source = os.environ.get("SCANTRACE_SOURCE_DIR")
    if not build or not source:
        pytest.skip("SCANTRACE_BUILD_DIR/SCANTRACE_SOURCE_DIR are not set (run through CTest)")
    before = source_files(source)
    dist = tmp_path / "dist"
    env = {**os.environ, "SCANTRACE_CMAKE_BUILD_DIR": build, "SCANTRACE_JOBS": "1"}
    subprocess.run([sys.executable, "-m", "build", "--wheel", "--no-isolation", "--outdir",
                    str(dist), source], check=True, capture_output=True, env=env)
    wheels = list(dist.glob("scantrace-*.whl"))
    assert len(wheels) == 1, wheels
    assert source_files(source) == before, "the wheel's build wrote into the clone"

    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)],
                   check=True, capture_output=True)
    python = venv / "bin" / "python"
    subprocess.run([str(python), "-m", "pip", "install", "--no-index", "--no-deps", "-q",
                    str(wheels[0])], check=True, capture_output=True)
    script = textwrap.dedent("""
        import numpy as np, scantrace
        img = scantrace.render_img([[0, 1, 2]], [[1, 1], [40, 2], [3, 30]], np.eye(3),
                                   np.zeros(3), 'g')
        scene = ([[0, 1, 2]], np.array([[1, 1], [40, 2], [3, 30]], float), np.eye(3), np.zeros(3))
        story = scantrace.why(scene, 10, 10)
        report = scantrace.diff(scene, img)
        player = scantrace.trace_triangle([[1, 1], [40, 2], [3, 30]], np.eye(3))._repr_html_()
        maps = open('/proc/self/maps').read()
        try:
            scantrace.explain([[1, 1], [40, 2], [3, 30]], np.eye(3), out='x/')
            missing = ''
        except ModuleNotFoundError as e:
            missing = str(e)
        print(scantrace.__file__)
        print(int((img != 1).any(axis=2).sum()), story.final['face'], report.agrees)
        print('opencv' in maps)
        print(missing)
        print('drawScantraceFrame' in player, 'function scantracePlayer' in player)
    """)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    out = subprocess.run([str(python), "-c", script], env=env, check=True, capture_output=True,
                         text=True, cwd=elsewhere).stdout.splitlines()
    assert pathlib.Path(out[0]).is_relative_to(venv)
    pixels, face, agrees = out[1].split()
    assert int(pixels) > 500 and face == "0" and agrees == "True"
    assert out[2] == "False", "import scantrace loaded OpenCV"
    assert "explain (writing a video or PNG frames) needs scantrace's OpenCV module" in out[3]
    assert "SCANTRACE_PYTHON_OPENCV=1" in out[3]
    # The inline player, with its script (package data of the wheel) and without OpenCV.
    assert out[4] == "True True"


def test_pip_install_builds_outside_the_clone(tmp_path):
    """Without SCANTRACE_CMAKE_BUILD_DIR, setup.py builds in the user's cache (XDG_CACHE_HOME),
    one directory per clone: `pip install .` writes nothing into the clone (setuptools' egg-info
    and build/ go there too)."""
    source = pathlib.Path(os.environ.get("SCANTRACE_SOURCE_DIR") or pathlib.Path(__file__).parents[2])
    env = {k: v for k, v in os.environ.items() if k != "SCANTRACE_CMAKE_BUILD_DIR"}
    env["XDG_CACHE_HOME"] = str(tmp_path / "cache")
    script = ("import runpy, setuptools\n"
              "setuptools.setup = lambda **kw: print(kw['options']['egg_info']['egg_base'])\n"
              "g = runpy.run_path('setup.py')\n"
              "print(g['BUILD'])\n")
    out = subprocess.run([sys.executable, "-c", script], cwd=source, env=env, check=True,
                         capture_output=True, text=True).stdout.split()
    egg_base, build = pathlib.Path(out[0]), pathlib.Path(out[1])
    assert build.parent.parent == tmp_path / "cache" / "scantrace" and build.is_dir()
    assert build.parent.name.startswith("python-") and build.name == "build"
    assert egg_base == build
    assert not build.is_relative_to(source.resolve())


FAKE_PROJECT = {
    # setup.py's configure and target, on a project of three small sources: a unity library (its
    # generated source #includes absolute paths, as io/ and trace/ do) and the module.
    "CMakeLists.txt": textwrap.dedent("""\
        cmake_minimum_required(VERSION 3.25)
        project(scantrace VERSION 0.0.1 LANGUAGES CXX)
        add_library(core STATIC src/a.cpp src/b.cpp)
        set_target_properties(core PROPERTIES UNITY_BUILD ON POSITION_INDEPENDENT_CODE ON)
        target_include_directories(core PUBLIC ${PROJECT_SOURCE_DIR})
        add_library(_scantrace MODULE python/module.cpp)
        target_link_libraries(_scantrace PRIVATE core)
        set_target_properties(_scantrace PROPERTIES PREFIX ""
                              LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/python/scantrace)
        """),
    "src/a.hpp": "int a();\nint b();\n",
    "src/a.cpp": '#include "src/a.hpp"\nint a() { return 1; }\n',
    "src/b.cpp": '#include "src/a.hpp"\nint b() { return 2; }\n',
    "python/module.cpp": '#include "src/a.hpp"\nint module_value() { return a() + b(); }\n',
}


def fake_clone(path):
    for name, text in FAKE_PROJECT.items():
        (path / name).parent.mkdir(parents=True, exist_ok=True)
        (path / name).write_text(text)
    shutil.copy(pathlib.Path(__file__).parents[2] / "setup.py", path / "setup.py")
    return path


def ccache_results(log):
    """The results ccache's stats log recorded for the project's own sources, one list per
    compile. CMake's compiler checks (its Modules/CMakeCXXCompilerABI.cpp) are left out: they go
    through ccache too when CMAKE_CXX_COMPILER_LAUNCHER is in the environment, as .ci/run exports
    it."""
    compiles = []
    for line in log.read_text().splitlines():
        if line.startswith("# "):
            compiles.append((line[2:], []))
        elif compiles:
            compiles[-1][1].append(line)
    return [results for source, results in compiles if "/Modules/CMake" not in source]


@pytest.mark.skipif(not shutil.which("ccache"), reason="ccache is not installed")
def test_pip_build_of_a_fresh_clone_reuses_another_clones_objects(tmp_path):
    """The compiles of setup.py's build (in the user's cache, outside the clone) are ccache hits
    when another clone at another path has built the same sources in its own build/, as
    scripts/build.sh and CI do: the speed of `pip install` from a warm cache. Nothing is written
    into the clone."""
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("CCACHE_", "SCANTRACE_CMAKE_BUILD_DIR"))}
    env.update(CCACHE_DIR=str(tmp_path / "ccache"), XDG_CACHE_HOME=str(tmp_path / "cache"))
    first = fake_clone(tmp_path / "one" / "scantrace")
    subprocess.run(["cmake", "-S", str(first), "-B", str(first / "build"),
                    "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"],
                   check=True, capture_output=True, env=env)
    subprocess.run(["cmake", "--build", str(first / "build")], check=True, capture_output=True,
                   env={**env, "CCACHE_BASEDIR": str(first)})

    second = fake_clone(tmp_path / "elsewhere" / "another-name")
    before = {p: p.read_bytes() for p in second.rglob("*") if p.is_file()}
    log = tmp_path / "second.log"
    # CCACHE_BASEDIR naming the clone, as scripts/build.sh exports it: setup.py sets its own.
    subprocess.run([sys.executable, "setup.py", "-q", "build_ext"], cwd=second, check=True,
                   capture_output=True,
                   env={**env, "CCACHE_STATSLOG": str(log), "CCACHE_BASEDIR": str(second)})
    results = ccache_results(log)
    assert len(results) == 2, results  # the unity source of core, the module's source
    assert all(any(r.endswith("_cache_hit") for r in c) for c in results), results
    assert {p: p.read_bytes() for p in second.rglob("*") if p.is_file()} == before
    built = list((tmp_path / "cache" / "scantrace").glob("python-*/build/python/scantrace/_scantrace*"))
    assert len(built) == 1, built
