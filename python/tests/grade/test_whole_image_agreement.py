"""Whole-image mistakes (transposed, BGR, background) are named alike by `diff` (C++,
grade/global_mistakes.cpp) and the grader (diagnose.diagnose_image), with the catalogue's one set
of thresholds (mistakes.json's whole_image): on the same images, the same ids, and none on a
correct image or one with a few wrong pixels. Each image is made here from the reference."""

import numpy as np
import pytest

import scantrace
from scantrace.grade import diagnose
from scantrace.grade.whole_image import whole_image_mistakes

SHADING = "f"


@pytest.fixture(scope="module")
def scene():
    return scantrace.demo_scene()


@pytest.fixture(scope="module")
def reference(scene):
    return scantrace.render_img(scene["faces"], scene["vertices"], scene["vcolors"],
                                scene["depth"], SHADING)


def _grey_background(scene):
    return scantrace.render(scene["vertices"], scene["faces"], scene["vcolors"], scene["depth"],
                            shading=SHADING, background=(0.99, 0.99, 0.99))


def _few_wrong(reference):
    img = reference.copy()
    img[100:104, 100:104] = (0.3, 0.2, 0.1)  # 16 wrong pixels: no whole-image mistake
    return img


IMAGES = {
    "correct": (lambda s, r: r.copy(), set()),
    "transposed": (lambda s, r: np.ascontiguousarray(r.transpose(1, 0, 2)), {"transposed"}),
    "bgr": (lambda s, r: np.ascontiguousarray(r[..., ::-1]), {"bgr"}),
    "grey background": (lambda s, r: _grey_background(s), {"background"}),
    "a few wrong pixels": (lambda s, r: _few_wrong(r), set()),
}


def _uncovered(scene, reference):
    black = scantrace.render(scene["vertices"], scene["faces"], scene["vcolors"],
                             scene["depth"], shading=SHADING, background=(0.0, 0.0, 0.0))
    return (reference == 1.0).all(axis=2) & (black == 0.0).all(axis=2)


@pytest.mark.parametrize("name", IMAGES)
def test_diff_and_the_grader_name_the_same_whole_image_mistakes(scene, reference, name):
    make, expected = IMAGES[name]
    img = make(scene, reference)
    from_diff = {g["kind"] for g in scantrace.diff(scene, img, shading=SHADING).global_mistakes}
    uncovered = _uncovered(scene, reference)
    _, causes = diagnose.diagnose_image(img, reference, uncovered, {})
    from_grader = {c.id for c in causes}
    fixed, whole, _ = whole_image_mistakes(img, reference, uncovered)
    assert from_diff == expected
    assert from_grader == expected
    assert {c.id for c in whole} == expected
    # Undone, the image is the reference again (its wrong patch aside).
    assert (np.abs(fixed - reference).max(axis=2) > 1.5 / 255).sum() <= 16


def test_the_grader_side_call_names_a_0_255_scale(scene, reference):
    """diff's scaled_255, through the grader's call (diagnose_image has no such cause yet)."""
    img = reference * 255
    fixed, causes, _ = whole_image_mistakes(img, reference, _uncovered(scene, reference))
    assert [c.id for c in causes] == ["scaled_255"]
    assert np.abs(fixed - reference).max() <= 1e-4
    assert causes[0].sentence == "The image holds colours on a 0–255 scale; the course's images " \
                                 "are floats in [0, 1]."
