"""One detector of the whole-image mistakes (transposed, flipped, BGR, background, a 0–255 scale):
diff's C++ (grade/global_mistakes.cpp), which the grader calls through whole_image.py. The grader's
diagnose.undo_global answers what the C++ answers (a stub in its place is followed word for
word), and on small images made here, whose right answer is worked out by hand, the grader undoes
the mistakes together: the transform on the faces' pixels, the background on the others, the
scale on the painted pixels only."""

import numpy as np
import pytest

import scantrace
from scantrace.grade import battery, diagnose, whole_image

FACE = (0.2, 0.4, 0.6)


def _scene_8x8():
    """An 8 x 8 reference: white, with an L of 7 pixels of FACE (column 1, rows 1..3, and row 3,
    columns 1..5), and the pixels no face covers. Transposed, it shares 2 pixels with itself,
    (1, 1) and (3, 3); flipped vertically or horizontally, none; with red and blue swapped, none:
    each transform at least doubles the pixels that match, and makes most of them match (more than
    the catalogue's quarter)."""
    ref = np.ones((8, 8, 3))
    ref[1:4, 1] = FACE
    ref[3, 1:6] = FACE
    return ref, (ref == 1.0).all(axis=2)


def test_the_grader_follows_whatever_the_cpp_detector_says(monkeypatch):
    """A stub in the C++'s place: undo_global names what it names, with its text as evidence,
    the share it gives as confidence, and returns its undone image: no second opinion."""
    ref, uncovered = _scene_8x8()
    undone = np.full_like(ref, 0.5)
    calls = []

    def stub(image, reference, faces, *, background, tolerance, undo):
        calls.append((faces.copy(), background, tolerance, undo))
        return ([{"kind": "flipped_vertically",
                  "text": "flipped (12 of 16 face pixels match after undoing it, 3 before)",
                  "undone": True}], undone, [])

    monkeypatch.setattr(whole_image._scantrace, "whole_image_mistakes", stub)
    fixed, causes = diagnose.undo_global(ref.copy(), ref, uncovered)
    assert fixed is undone
    assert [c.id for c in causes] == ["flipped_vertically"]
    assert causes[0].evidence == "flipped (12 of 16 face pixels match after undoing it, 3 before)"
    assert causes[0].confidence == 12 / 16
    faces, background, tolerance, undo = calls[0]
    assert (faces == ~uncovered).all() and background == (1.0, 1.0, 1.0) and undo
    assert tolerance == 1.5 / 255


@pytest.mark.parametrize("name", ["transposed", "bgr", "flipped_vertically",
                                  "transposed on 0.99", "bgr on 0.99", "transposed+bgr",
                                  "transposed+bgr on 0.99"])
def test_whole_image_mistakes_are_undone_together(name):
    ref, uncovered = _scene_8x8()
    img = ref.copy()
    if "0.99" in name:
        img[uncovered] = 0.99               # a canvas of 0.99 under the faces
    if name.startswith("transposed"):
        img = np.ascontiguousarray(img.transpose(1, 0, 2))
    if name.startswith("bgr") or "+bgr" in name:
        img = np.ascontiguousarray(img[..., ::-1])
    if name == "flipped_vertically":
        img = np.ascontiguousarray(img[::-1])
    fixed, causes = diagnose.undo_global(img, ref, uncovered)
    # transposed+bgr: the transposed L with red and blue swapped matches the reference nowhere
    # (neither alone makes more than 2 of its 7 pixels match), both undone all 7.
    expected = name.split()[0].split("+") + (["background"] if "0.99" in name else [])
    assert [c.id for c in causes] == expected
    # Undone together, the image is the reference: every pixel within float32's rounding.
    assert np.abs(fixed - ref).max() < 1e-6
    if "0.99" in name:
        assert causes[-1].detail == "(0.99, 0.99, 0.99)"
        assert causes[-1].sentence == "The background is (0.99, 0.99, 0.99) instead of white " \
                                      "(1, 1, 1)."
        assert causes[-1].confidence == 1.0          # 57 of the 57 uncovered pixels


def test_a_few_wrong_pixels_are_no_whole_image_mistake():
    ref, uncovered = _scene_8x8()
    img = ref.copy()
    img[1:3, 1] = (0.9, 0.1, 0.1)           # 2 of the L's 7 pixels
    fixed, causes = diagnose.undo_global(img, ref, uncovered)
    assert causes == [] and fixed is img


def test_a_0_255_fill_on_the_blank_canvas_rescales_the_painted_pixels_alone():
    """colour * 255 written on the grader's canvas of ones: the L becomes FACE again and the
    canvas stays white (divided too, it would be 1/255: black)."""
    ref, uncovered = _scene_8x8()
    img = ref.copy()
    img[~uncovered] = np.multiply(FACE, 255)
    fixed, top = whole_image.scale_255(img)
    assert top == pytest.approx(0.6 * 255)
    assert (fixed[uncovered] == 1.0).all()
    assert np.abs(fixed[~uncovered] - FACE).max() < 1e-6


def test_a_canvas_of_its_own_at_255_is_divided_whole():
    ref, _ = _scene_8x8()
    fixed, top = whole_image.scale_255(ref * 255)
    assert top == 255
    assert np.abs(fixed - ref).max() < 1e-6


def test_black_says_nothing_about_the_scale():
    """A black canvas (np.zeros) with the L at 255 x FACE: 7 painted pixels, all above 1, so
    a 0–255 image though 57 of its 64 pixels are 0 (black is 0 on both scales)."""
    ref, uncovered = _scene_8x8()
    img = np.zeros((8, 8, 3))
    img[~uncovered] = np.multiply(FACE, 255)
    fixed, top = whole_image.scale_255(img)
    assert top is not None
    assert (fixed[uncovered] == 0).all() and np.abs(fixed[~uncovered] - FACE).max() < 1e-6


def test_a_few_values_above_1_are_no_scale():
    """One pixel at 1.01 (a Gouraud colour extrapolated a little) on a right image: 1 of the 7
    painted pixels above 1, not more than half of them: kept as it is, as diff keeps it."""
    ref, _ = _scene_8x8()
    img = ref.copy()
    img[1, 1] = (1.01, 0.5, 0.5)
    fixed, top = whole_image.scale_255(img)
    assert top is None and fixed is img


def test_battery_canvases_go_through_the_same_scale():
    ref, uncovered = _scene_8x8()
    img = ref.copy()
    img[~uncovered] = np.multiply(FACE, 255)
    fixed, top = battery.canvas(img, (8, 8, 3))
    assert top == pytest.approx(0.6 * 255) and (fixed[uncovered] == 1.0).all()


def test_diff_and_the_grader_name_the_same_mistakes_on_the_demo_scene():
    """The same C++ behind both: on the demo scene on a 0.99 background, transposed, diff's
    global mistakes and the grader's causes are the same two."""
    scene = scantrace.demo_scene()
    args = (scene["vertices"], scene["faces"], scene["vcolors"], scene["depth"])
    reference = scantrace.render(*args, shading="flat")
    grey = scantrace.render(*args, shading="flat", background=(0.99, 0.99, 0.99))
    black = scantrace.render(*args, shading="flat", background=(0.0, 0.0, 0.0))
    uncovered = (reference == 1.0).all(axis=2) & (black == 0.0).all(axis=2)
    img = np.ascontiguousarray(grey.transpose(1, 0, 2))
    from_diff = {g["kind"] for g in scantrace.diff(scene, img, shading="flat").global_mistakes}
    fixed, causes = diagnose.undo_global(img, reference, uncovered)
    assert from_diff == {c.id for c in causes} == {"transposed", "background"}
    assert (diagnose.channel_error(fixed, reference) > 1.5 / 255).sum() == 0


def test_a_transposed_image_with_other_mistakes_besides_is_still_undone():
    """16 x 16, an L of 21 pixels (column 1, rows 1..10; row 10, columns 2..12), 12 of them
    painted a wrong colour (column 1, rows 2..10; row 10, columns 10..12), then transposed: read
    as it is, 1 face pixel matches ((1, 1)); transposed back, the 9 right ones do — 4.5 times as
    many, but 9 of 21, under half. A quarter is enough to undo it, so the 9 count as right."""
    ref = np.ones((16, 16, 3))
    ref[1:11, 1] = FACE
    ref[10, 2:13] = FACE
    uncovered = (ref == 1.0).all(axis=2)
    wrong = ref.copy()
    wrong[2:11, 1] = (0.9, 0.1, 0.1)
    wrong[10, 10:13] = (0.9, 0.1, 0.1)
    fixed, causes = diagnose.undo_global(np.ascontiguousarray(wrong.transpose(1, 0, 2)), ref,
                                         uncovered)
    assert [c.id for c in causes] == ["transposed"]
    assert "(9 of 21 face pixels match after undoing it, 1 before)" in causes[0].evidence
    assert np.abs(fixed - wrong).max() < 1e-6
