"""examples/python/course.ipynb executed as a student runs it (nbclient and an ipykernel kernel of
this interpreter): a cell that raises fails the test. Then its outputs are what each cell
promises, and its static HTML export (nbconvert; no kernel) opened in headless Chromium shows the
trace player stepping. Without the course scene the notebook runs on the built-in one."""

import json
import os
import shutil
import sys

import pytest

from conftest import SHARED_DATA, SOURCE_DIR, run_in_chromium

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")

NOTEBOOK = SOURCE_DIR / "examples" / "python" / "course.ipynb"
COURSE_NPY = SHARED_DATA / "hw1_2024.npy"


def execute(tmp_path, monkeypatch, scene):
    monkeypatch.setenv("SCANTRACE_COURSE_SCENE", str(scene))
    # The kernel runs in tmp_path: the package's directory must be absolute to be found there.
    path = os.environ.get("PYTHONPATH", "")
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(os.path.abspath(p) for p in path.split(os.pathsep) if p))
    monkeypatch.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # the kernel's debugger's warning
    nb = nbformat.read(NOTEBOOK, as_version=4)
    for cell in nb.cells:  # the notebook is kept without outputs (a clean diff)
        assert cell.cell_type != "code" or not cell.outputs
    # Executed as shipped: with the kernel its metadata names, the README's `scantrace` (what
    # `python -m ipykernel install --user --name scantrace` makes), here one of this interpreter
    # in a kernel directory of the test's own: it inherits PYTHONPATH.
    name = nb.metadata.kernelspec.name
    kernel_dir = tmp_path / "jupyter" / "kernels" / name
    kernel_dir.mkdir(parents=True, exist_ok=True)
    (kernel_dir / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": name, "language": "python"}))
    monkeypatch.setenv("JUPYTER_PATH", str(tmp_path / "jupyter"))
    nbclient.NotebookClient(nb, timeout=300,
                            resources={"metadata": {"path": str(tmp_path)}}).execute()
    return nb


def outputs(nb, source_start):
    """The outputs of the code cell whose source starts with source_start."""
    cells = [c for c in nb.cells if c.cell_type == "code" and c.source.startswith(source_start)]
    assert len(cells) == 1, source_start
    return cells[0].outputs


def data_of(outs, mime):
    found = [o["data"][mime] for o in outs if o.get("data", {}).get(mime)]
    assert found, f"no {mime} output"
    return found[0]


@pytest.fixture(scope="module")
def builtin_run(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("notebook")
    with pytest.MonkeyPatch.context() as mp:
        return execute(tmp, mp, tmp / "absent.npy"), tmp


def test_the_notebook_names_the_readmes_kernel():
    """The README makes a kernel named `scantrace`; the shipped notebook asks for that one (it
    named `python3`, whose interpreter need not have scantrace: ModuleNotFoundError)."""
    nb = nbformat.read(NOTEBOOK, as_version=4)
    assert nb.metadata.kernelspec.name == "scantrace"
    readme = (SOURCE_DIR / "README.md").read_text(encoding="utf-8")
    assert f"-m ipykernel install --user --name {nb.metadata.kernelspec.name}" in readme


def test_the_notebook_runs_on_the_builtin_scene(builtin_run):
    nb, _ = builtin_run
    text = "".join(o.get("text", "") for o in outputs(nb, "import os"))
    assert text.startswith("the built-in demo scene: ") and "512x512" in text
    assert data_of(outputs(nb, "reference = "), "image/png")
    assert data_of(outputs(nb, "def my_f_shading"), "image/png")
    diff_html = data_of(outputs(nb, "report = "), "text/html")
    assert "pixels differ" in diff_html and "data:image/png;base64," in diff_html
    story = data_of(outputs(nb, "ys, xs = "), "text/markdown")
    assert story.startswith("**Pixel (")
    player = data_of(outputs(nb, "t = scantrace.trace_triangle"), "text/html")
    assert 'class="scantrace-player"' in player and len(player) <= 1_000_000
    assert "Scanline(triangle=0, y=100" in data_of(outputs(nb, "row = "), "text/plain")


DRIVER = """<script>
window.addEventListener('load', async function () {
  const root = document.querySelector('.scantrace-player');
  const shown = (k) => new Promise((ok) => {
    const t = setInterval(() => { if (root.dataset.shown === String(k)) { clearInterval(t); ok(); } }, 5);
  });
  const key = (k) => root.dispatchEvent(new KeyboardEvent('keydown', {key: k, bubbles: true}));
  const n = root.scantrace.deck.frames.length;
  const seen = [];
  const look = () => seen.push([Number(root.dataset.shown), root.querySelector('.st-label').textContent]);
  await shown(0); look();
  key('ArrowRight'); await shown(1); look();
  key('End'); await shown(n - 1); look();
  const pre = document.createElement('pre');
  pre.id = 'result';
  pre.textContent = JSON.stringify({steps: n, seen: seen});
  document.body.appendChild(pre);
});
</script>"""


@pytest.mark.skipif(not shutil.which("chromium"), reason="chromium is not installed")
@pytest.mark.filterwarnings("ignore::DeprecationWarning")  # nbconvert 6.5's own call of nbformat
def test_the_static_html_export_steps_the_player_in_chromium(builtin_run):
    nbconvert = pytest.importorskip("nbconvert")
    nb, tmp = builtin_run
    page, _ = nbconvert.HTMLExporter().from_notebook_node(nb)
    assert page.count('class="scantrace-player"') == 1
    path = tmp / "course.html"
    path.write_text(page.replace("</body>", DRIVER + "</body>"))
    out = run_in_chromium(path, tmp)
    n = out["steps"]
    assert n == 47  # the course triangle's replay, every step within the 1 MB bound
    assert out["seen"] == [[0, "title"], [1, "triangle 0: set-up"], [n - 1, "end"]]


@pytest.mark.skipif(not COURSE_NPY.exists(), reason=f"the course scene {COURSE_NPY} is not here")
def test_the_notebook_runs_on_the_course_hw1_npy(tmp_path, monkeypatch):
    nb = execute(tmp_path, monkeypatch, COURSE_NPY)
    text = "".join(o.get("text", "") for o in outputs(nb, "import os"))
    assert text.startswith(f"{COURSE_NPY}: 10000 faces") and "512x512" in text
    report = data_of(outputs(nb, "report = "), "text/html")
    assert "pixels differ" in report
    json.dumps(nb)  # every output is plain JSON (what a notebook file holds)
