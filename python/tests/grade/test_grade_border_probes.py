"""The canvas-border probes and the shared edge through f_shading (probes.py): each catches a
deliberately wrong submission written in the course's style, and the correct submission passes
them (test_grade_causes_fill.py: full marks, no cause)."""

import numpy as np
import pytest

import scantrace
from scantrace.grade import fill_models
from scantrace.grade.probes import PROBES

from conftest import grade_source, wrong_source

BORDER = {p.name: p for p in PROBES if p.name.startswith("border_")}


def test_each_border_probe_fills_its_border_line():
    """Independently of the models: the C++ fill writes the probe's first or last column or row,
    so a bounds check off by one at that end changes the image."""
    touches = {"border_left": lambda m: m[:, 0], "border_top": lambda m: m[0, :],
               "border_right": lambda m: m[:, -1], "border_bottom": lambda m: m[-1, :],
               "border_corner": lambda m: np.concatenate([m[:, -1], m[-1, :]])}
    assert set(touches) == set(BORDER)
    for name, line in touches.items():
        p = BORDER[name]
        img = scantrace.f_shading(np.ones((*p.size, 3)), p.array, np.full((3, 3), 0.3))
        filled = np.any(img != 1, axis=2)
        assert line(filled).sum() >= 10, name
        assert (filled == fill_models.correct(p.array, p.size)).all(), name


@pytest.mark.parametrize("variant, detail, probes", [
    ("canvas_border_clipped", "first column and row", ("border_left", "border_top")),
    ("canvas_border_clipped_last", "last column and row",
     ("border_right", "border_bottom", "border_corner")),
])
def test_bounds_check_off_by_one_is_named(tmp_path, sandbox_ok, variant, detail, probes):
    graded = grade_source(tmp_path, wrong_source(variant))
    assert [c.id for c in graded.causes] == ["canvas_border_clipped"]
    cause = graded.causes[0]
    assert detail in cause.sentence
    assert any(f"probe `{p}`" in cause.evidence for p in probes), cause.evidence
    flat = next(t for t in graded.tests if t.name.startswith("Probes: flat fill"))
    assert flat.status == "failed"
    # Exactly the border probes of that end fail, each named on its own line.
    failing = {p.name for p in PROBES if f"probe `{p.name}`" in flat.output}
    assert failing == set(probes), flat.output


def test_shared_edge_through_f_shading_catches_the_closed_rule(tmp_path, sandbox_ok):
    """A closed rule draws the shared diagonal with both faces: the f_shading pair says so (the
    single-triangle probes cannot: each face alone is a different mistake's evidence)."""
    graded = grade_source(tmp_path, wrong_source("closed_rule"))
    flat = next(t for t in graded.tests if t.name.startswith("Probes: flat fill"))
    assert "probe pair `shared_edge`" in flat.output, flat.output
    line = next(l for l in flat.output.splitlines() if "probe pair `shared_edge`" in l)
    assert "pixels differ" in line and "first on row" in line
