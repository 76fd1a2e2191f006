"""The pairs probe (probes.PAIRS through render_img): two faces sharing an edge, two of equal mean
depth, two of distinct depths. Without any hidden scene the painter's-order mistakes are named
from it, with its picture, and the closed rule shows on the shared edge."""

import numpy as np
import pytest

import scantrace
from scantrace.grade.probes import PAIR_REGIONS, PAIRS

from conftest import grade_source, wrong_source


def _pairs_test(graded):
    return next(t for t in graded.tests if t.name.startswith("Probes: pairs of faces"))


def test_the_pairs_are_what_they_claim():
    # Independently of the grader: the mean depths tie for faces 2 and 3 and not for the others,
    # faces 0 and 1 share two vertices, and the flat reference draws every pair in its region.
    depth = PAIRS["depth"][PAIRS["faces"]].mean(axis=1)
    assert depth[2] == depth[3] and len({depth[0], depth[1], depth[4], depth[5], depth[2]}) == 5
    assert len(set(PAIRS["faces"][0]) & set(PAIRS["faces"][1])) == 2
    img = scantrace.render_img(PAIRS["faces"], PAIRS["vertices"], PAIRS["vcolors"],
                               PAIRS["depth"], "f")
    drawn = np.any(img != 1, axis=2)
    assert sum(int(drawn[region].sum()) for _, _, _, region in PAIR_REGIONS) == drawn.sum()


@pytest.mark.parametrize("cause,pair", [("order_unstable_on_ties", "tied_depths"),
                                        ("order_reversed", "distinct_depths")])
def test_order_is_named_from_the_pairs_without_hidden_scenes(tmp_path, sandbox_ok, cause, pair):
    graded = grade_source(tmp_path, wrong_source(cause), hidden_seed=None)
    assert [c.id for c in graded.causes] == [cause]
    assert graded.causes[0].evidence.startswith("probe scene `pairs`")
    assert (tmp_path / "student-out" / "causes" / f"{cause}.png").exists()
    test = _pairs_test(graded)
    assert test.score < test.max_score and f"pair `{pair}`" in test.output
    assert sum(f"pair `{p}`" in test.output for p, _, _, _ in PAIR_REGIONS) == 1


def test_the_closed_rule_shows_on_the_shared_edge(tmp_path, sandbox_ok):
    graded = grade_source(tmp_path, wrong_source("closed_rule"), hidden_seed=None)
    assert [c.id for c in graded.causes] == ["closed_rule"]
    assert "pair `shared_edge`" in _pairs_test(graded).output
