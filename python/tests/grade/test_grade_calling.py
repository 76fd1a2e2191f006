"""Student code written as the course's students write it, graded through its own functions: it
assumes the course's calling convention (numpy arrays with hw1.npy's dtypes: int64 vertices in
`range()`, `V1 + t * (V2 - V1)` on arrays), keeps edges in dictionaries with active points (as the
real student's report in ../shared/seeds describes), or follows another year's API. Each is held
to full marks on the assignment's domain (the correct ones) or to its cause."""

import dataclasses
import pathlib
import textwrap

import numpy as np
import pytest

from scantrace.grade import diagnose, fill_models
from scantrace.grade.grader import course_arrays, grade
from scantrace.grade.probes import GOURAUD, PROBES

from scantrace.grade.sandbox import Limits

from conftest import (CORRECT, WRONG, grade_source, quick_options, write_submission,
                      wrong_source)

# A correct solution that relies on the course's types: vertices[:, 1].min() is an int64 that
# range() accepts (a float64 raises "'numpy.float64' object cannot be interpreted as an
# integer"), and vector_interp subtracts V1 from V2 with no np.asarray (lists cannot). Edges are
# dictionaries, the active points are sorted by x, the rows run to y_max + 1 (the last one has no
# active edge under the half-open test, so it draws nothing), the painter's order is a stable
# sort of dictionaries by mean depth.
INT64_STUDENT = textwrap.dedent('''\
    import math
    import numpy as np


    def vector_interp(p1, p2, V1, V2, coord, dim):
        if p1[dim - 1] == p2[dim - 1]:
            return V1
        t = (coord - p1[dim - 1]) / (p2[dim - 1] - p1[dim - 1])
        return V1 + t * (V2 - V1)


    def make_edges(vertices, vcolors):
        edges = []
        for i in range(3):
            j = (i + 1) % 3
            if vertices[i][1] == vertices[j][1]:
                continue  # a horizontal edge is never active
            top, bottom = (i, j) if vertices[i][1] < vertices[j][1] else (j, i)
            edges.append({
                "y_min": vertices[top][1], "y_max": vertices[bottom][1],
                "top": vertices[top], "bottom": vertices[bottom],
                "c_top": vcolors[top], "c_bottom": vcolors[bottom],
                "inv_slope": (vertices[bottom][0] - vertices[top][0])
                             / (vertices[bottom][1] - vertices[top][1]),
            })
        return edges


    def active_points(edges, y):
        points = []
        for e in edges:
            if e["y_min"] <= y < e["y_max"]:
                points.append((e["top"][0] + (y - e["y_min"]) * e["inv_slope"], e))
        points.sort(key=lambda p: p[0])
        return points


    def f_shading(img, vertices, vcolors):
        colour = np.mean(vcolors, axis=0)
        edges = make_edges(vertices, vcolors)
        for y in range(vertices[:, 1].min(), vertices[:, 1].max() + 1):
            points = active_points(edges, y)
            if len(points) < 2:
                continue
            for x in range(math.ceil(points[0][0]), math.ceil(points[1][0])):
                if 0 <= x < img.shape[1] and 0 <= y < img.shape[0]:
                    img[y, x] = colour
        return img


    def g_shading(img, vertices, vcolors):
        edges = make_edges(vertices, vcolors)
        for y in range(vertices[:, 1].min(), vertices[:, 1].max() + 1):
            points = active_points(edges, y)
            if len(points) < 2:
                continue
            (xa, ea), (xb, eb) = points[0], points[1]
            ca = vector_interp(ea["top"], ea["bottom"], ea["c_top"], ea["c_bottom"], y, 2)
            cb = vector_interp(eb["top"], eb["bottom"], eb["c_top"], eb["c_bottom"], y, 2)
            for x in range(math.ceil(xa), math.ceil(xb)):
                if 0 <= x < img.shape[1] and 0 <= y < img.shape[0]:
                    img[y, x] = vector_interp(np.array([xa, y]), np.array([xb, y]), ca, cb, x, 1)
        return img


    def render_img(faces, vertices, vcolors, depth, shading):
        img = np.ones((512, 512, 3))
        triangles = []
        for face in faces:
            triangles.append({"vertices": vertices[face], "colors": vcolors[face],
                              "depth": np.mean(depth[face])})
        triangles.sort(key=lambda t: t["depth"], reverse=True)  # stable: ties keep face order
        for t in triangles:
            if shading == "f":
                img = f_shading(img, t["vertices"], t["colors"])
            else:
                img = g_shading(img, t["vertices"], t["colors"])
        return img


    if __name__ == "__main__":
        data = np.load("hw1.npy", allow_pickle=True).item()
        render_img(data["faces"], data["vertices"], data["vcolors"], data["depth"], "f")
    ''')


def _test(graded, start):
    return next(t for t in graded.tests if t.name.startswith(start))


def test_int64_student_is_graded_through_its_own_code(tmp_path, sandbox_ok):
    graded = grade_source(tmp_path, INT64_STUDENT)
    # vector_interp gets numpy arrays: V2 - V1 works (Python lists raised TypeError).
    assert _test(graded, "vector_interp: ordinary").status == "passed"
    assert _test(graded, "vector_interp: degenerate").status == "passed"
    # The scenes pass int64 vertices, face by face included: the render is exact.
    for t in graded.tests:
        if t.name.startswith(("Hidden scene", "Probes: pairs")):
            assert t.status == "passed", (t.name, t.output)
    assert graded.causes == []
    # Every probe in the assignment's domain passes; only the non-integer ones (range() of a
    # float64) fail, and they are marked beyond the assignment.
    outcomes = [p for start in ("Probes: flat", "Probes: Gouraud")
                for p in _test(graded, start).probes]
    assert len(outcomes) == len(PROBES) + len(GOURAUD)
    assert [p.name for p in outcomes if not p.passed] == \
        [p.name for p in PROBES if not p.integer] == ["non_integer", "halves"]
    assert all(p.status == "error" for p in outcomes if not p.passed)
    flat = _test(graded, "Probes: flat").output
    # One line for both (the same TypeError), each probe named beyond the assignment.
    failing = [line for line in flat.splitlines() if line.startswith("- ")]
    assert len(failing) == 1 and failing[0].startswith("- 2 calls failing the same way")
    assert failing[0].count("beyond the assignment") == 2
    assert flat.count("TypeError") == 1


# Another year's API, written independently of the course's 2024 one: interpolate_vectors,
# shade_triangle(img, verts2d, vcolors, shade_t) with 'flat' / 'gouraud', and
# render(verts2d, faces, vcolors, depth, shade_t) (vertices before faces). The fill is right.
OTHER_YEAR = textwrap.dedent('''\
    import numpy as np


    def interpolate_vectors(p1, p2, V1, V2, xy, dim):
        a, b = p1[dim - 1], p2[dim - 1]
        if a == b:
            return np.array(V1, dtype=float)
        lam = (xy - a) / (b - a)
        return (1 - lam) * np.array(V1, dtype=float) + lam * np.array(V2, dtype=float)


    def shade_triangle(img, verts2d, vcolors, shade_t):
        verts2d = np.array(verts2d, dtype=float)
        order = np.argsort(verts2d[:, 1], kind="stable")
        v, c = verts2d[order], np.array(vcolors, dtype=float)[order]
        flat = np.mean(c, axis=0)
        (x0, y0), (x1, y1), (x2, y2) = v
        if (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0) == 0:
            return img
        for y in range(int(np.ceil(y0)), int(np.ceil(y2))):
            xa = x0 + (y - y0) * (x2 - x0) / (y2 - y0)            # the long edge
            ca = interpolate_vectors(v[0], v[2], c[0], c[2], y, 2)
            if y < y1:
                xb = x0 + (y - y0) * (x1 - x0) / (y1 - y0)
                cb = interpolate_vectors(v[0], v[1], c[0], c[1], y, 2)
            else:
                xb = x1 + (y - y1) * (x2 - x1) / (y2 - y1)
                cb = interpolate_vectors(v[1], v[2], c[1], c[2], y, 2)
            if xa > xb:
                xa, xb, ca, cb = xb, xa, cb, ca
            for x in range(int(np.ceil(xa)), int(np.ceil(xb))):
                if 0 <= x < img.shape[1] and 0 <= y < img.shape[0]:
                    if shade_t == "flat":
                        img[y, x] = flat
                    elif shade_t == "gouraud":
                        img[y, x] = interpolate_vectors((xa, y), (xb, y), ca, cb, x, 1)
                    else:
                        raise ValueError("shade_t must be 'flat' or 'gouraud'")
        return img


    def render(verts2d, faces, vcolors, depth, shade_t):
        img = np.ones((512, 512, 3))
        face_depth = np.array([np.mean(depth[f]) for f in faces])
        for k in np.argsort(-face_depth, kind="stable"):
            shade_triangle(img, verts2d[faces[k]], vcolors[faces[k]], shade_t)
        return img
    ''')


# The same on 0–255 canvases: its render starts from 255s, its fill writes colour * 255 (also on
# the grader's canvas of ones, whose white must stay white).
OTHER_YEAR_255 = OTHER_YEAR.replace("img = np.ones((512, 512, 3))",
                                    "img = np.full((512, 512, 3), 255.0)").replace(
    "img[y, x] = flat\n", "img[y, x] = flat * 255\n").replace(
    "img[y, x] = interpolate_vectors((xa, y), (xb, y), ca, cb, x, 1)\n",
    "img[y, x] = 255 * interpolate_vectors((xa, y), (xb, y), ca, cb, x, 1)\n")


@pytest.mark.parametrize("source", [OTHER_YEAR, OTHER_YEAR_255], ids=["unit", "0-255"])
def test_other_years_api_is_graded_through_an_adapter(tmp_path, sandbox_ok, source):
    assert source == OTHER_YEAR or source.count("255") == 3
    graded = grade_source(tmp_path, source)
    assert not graded.error and len(graded.tests) >= 8
    # The 0–255 scale is a mistake of its own, named with its deduction (graded after a rescale).
    scaled = [] if source == OTHER_YEAR else ["scaled_255"]
    assert [t.name for t in graded.tests if t.status != "passed"] == \
        [f"Deduction: {c}" for c in scaled]
    assert [c.id for c in graded.causes] == ["other_api"] + scaled
    evidence = graded.causes[0].evidence
    for text in ("shade_triangle(img, verts2d, vcolors, shade_t)` for `f_shading` with "
                 "shade_t = 'flat'", "for `g_shading` with shade_t = 'gouraud'",
                 "render(verts2d, faces, vcolors, depth, shade_t)` for `render_img` with "
                 "shading 'flat' / 'gouraud'", "interpolate_vectors("):
        assert text in evidence
    # Said once, in one line.
    assert len([n for n in graded.notes if "another year's API" in n]) == 1


def test_render_img_with_a_canvas_parameter(tmp_path, sandbox_ok):
    """render_img(faces, vertices, vcolors, depth, shading, img) filling the canvas it is given
    in place: called with a blank canvas, which is then the image."""
    source = INT64_STUDENT.replace(
        "def render_img(faces, vertices, vcolors, depth, shading):\n"
        "    img = np.ones((512, 512, 3))\n",
        "def render_img(faces, vertices, vcolors, depth, shading, img):\n").replace(
        "            img = g_shading(img, t[\"vertices\"], t[\"colors\"])\n    return img\n",
        "            img = g_shading(img, t[\"vertices\"], t[\"colors\"])\n")
    assert "shading, img):" in source and source.count("return img") == 2
    graded = grade_source(tmp_path, source)
    assert [c.id for c in graded.causes] == ["other_api"]
    assert "render_img(faces, vertices, vcolors, depth, shading, img)` (given a blank canvas)" \
        in graded.causes[0].evidence
    for t in graded.tests:
        if t.name.startswith(("Hidden scene", "Probes: pairs")):
            assert t.status == "passed", (t.name, t.output)


# The vertices rounded to whole pixels before the fill, as `int(round(x))`: harmless on the
# course's integer vertices, visible only on the non-integer probes (beyond the assignment).
ROUNDED = ("vertices = np.asarray(vertices, dtype=float)\n",
           "vertices = np.array([[int(round(x)), int(round(y))] for x, y in vertices], "
           "dtype=float)\n")


# Truncated instead (`astype(int)`): no fill model draws that, so the non-integer probes' rows
# stay unexplained; they must not outvote the integer probes.
TRUNCATED = (ROUNDED[0], "vertices = np.asarray(vertices).astype(int).astype(float)\n")


@pytest.mark.parametrize("vertices", [ROUNDED, TRUNCATED], ids=["rounded", "truncated"])
@pytest.mark.parametrize("cause", ["closed_rule", "span_end_rounding", "bottom_row_dropped",
                                   "edge_lag"])
def test_a_fill_rounding_its_vertices_keeps_its_cause(tmp_path, sandbox_ok, cause, vertices):
    """The non-integer probes cannot prevent the cause the integer probes show (they did: one
    model had to explain 90 % of the wrong rows over all probes)."""
    source = wrong_source(cause)
    assert source.count(vertices[0]) == 1
    graded = grade_source(tmp_path, source.replace(*vertices))
    assert [c.id for c in graded.causes] == [cause]
    if vertices == ROUNDED:
        assert "rounded to whole pixels" in graded.causes[0].evidence


def test_a_fill_rounding_its_vertices_alone_has_no_cause(tmp_path, sandbox_ok):
    graded = grade_source(tmp_path, CORRECT.replace(*ROUNDED))
    assert graded.causes == []
    outcomes = [p for t in graded.tests for p in t.probes]
    assert {p.name for p in outcomes if not p.passed} == {"non_integer", "halves"}


@pytest.mark.parametrize("causes", [("right_end_excluded", "bottom_row_dropped"),
                                    ("span_end_rounding", "edge_lag"),
                                    ("span_too_wide", "top_row_dropped")])
def test_two_fill_mistakes_are_both_named(tmp_path, sandbox_ok, causes):
    """A composition of two fill models explains what neither explains alone."""
    source = CORRECT
    for cause in causes:
        for edit in WRONG[cause]:
            source = edit(source)
    graded = grade_source(tmp_path, source)
    assert [c.id for c in graded.causes] == list(causes)
    assert "together explain it" in graded.causes[0].evidence


def test_compositions_reproduce_the_one_mistake_models():
    """Independently written: each one-mistake model of fill_models.MODELS is the composition
    with its one axis off, on every probe."""
    # (float_drift's model is itself the composition: the graded accumulating student of
    # test_grade_causes_fill.py checks it.)
    axes = {"span_end_rounding": 0, "right_end_excluded": 0, "span_too_wide": 0,
            "top_row_dropped": 1, "bottom_row_dropped": 1, "edge_lag": 2}
    for (cause, variant), model in fill_models.MODELS.items():
        if cause not in axes and cause != "closed_rule":
            continue
        composition = [None] * 4
        for axis in ([0, 1] if cause == "closed_rule" else [axes[cause]]):
            composition[axis] = (cause, variant)
        for p in PROBES:
            composer = fill_models.Composer(p.array, p.size)
            assert (composer.mask(tuple(composition)) == model(p.array, p.size)).all(), \
                (cause, variant, p.name)
            assert fill_models.row_spans(model(p.array, p.size)) == \
                composer.rows(tuple(composition))


def test_first_wrong_row():
    expected = np.zeros((10, 20), bool)
    expected[7, 12:19] = True
    student = expected.copy()
    student[7, 11] = True
    assert diagnose.first_wrong_row(student, expected) == "row 7: expected 12..18, yours 11..18"
    student = expected.copy()
    student[7] = False
    student[8, 3:5] = student[8, 9:11] = True
    assert diagnose.first_wrong_row(student, expected) == "row 7: expected 12..18, yours nothing"
    assert diagnose.first_wrong_row(expected, student) == "row 7: expected nothing, yours 12..18"
    assert diagnose.first_wrong_row(student[8:], expected[8:]) == \
        "row 0: expected nothing, yours 3..4, 9..10"
    assert diagnose.first_wrong_row(expected, expected) == ""


def _scene_tests(graded):
    return [t for t in graded.tests if t.name.startswith(("Hidden scene", "Course scene"))]


def test_transposed_on_a_grey_background_is_undone_together(tmp_path, sandbox_ok):
    """img[x][y] on a canvas of 0.99: undoing either alone leaves most pixels different (the
    background is most of the image), so each must be tried with the other."""
    source = CORRECT
    for edit in WRONG["transposed"]:
        source = edit(source)
    source = source.replace("img = np.ones((512, 512, 3))  # CANVAS",
                            "img = np.full((512, 512, 3), 0.99)  # CANVAS")
    graded = grade_source(tmp_path, source)
    assert sorted(c.id for c in graded.causes) == ["background", "transposed"]
    scenes = _scene_tests(graded)
    assert len(scenes) == 4
    for t in scenes:
        assert t.status == "passed", (t.name, t.output)
        assert "after undoing transposed, background" in t.output


def test_painted_pixels_in_0_255_are_rescaled_alone(tmp_path, sandbox_ok):
    """colour * 255 written on the grader's canvas of ones: the painted pixels are rescaled,
    the untouched white stays white (dividing it too made every probe wrong everywhere). The
    rest is graded after the rescale; the scale itself is named once (scaled_255), with the
    tests that showed it."""
    source = CORRECT.replace("img[y, x] = colour  # PUT",
                             "img[y, x] = np.asarray(colour) * 255  # PUT")
    graded = grade_source(tmp_path, source)
    assert [c.id for c in graded.causes] == ["scaled_255"]
    evidence = graded.causes[0].evidence
    assert "the f_shading probes" in evidence and "Hidden scene 1: flat" in evidence
    assert "255" in evidence and "0–255" in graded.causes[0].sentence
    assert [t.name for t in graded.tests if t.status != "passed"] == ["Deduction: scaled_255"]
    assert all("0–255 range" in t.output for t in _scene_tests(graded))
    # The rubric's deduction for it, as for the other mistakes the grader undoes.
    assert graded.score == graded.max_score - 5


def test_render_img_returning_uint8_is_named_once(tmp_path, sandbox_ok):
    """render_img returning `(img * 255).astype(np.uint8)` (for cv2.imwrite), its fills in
    [0, 1]: the scenes are right once rescaled, and scaled_255 names render_img's tests only."""
    source = INT64_STUDENT.replace(
        "            img = g_shading(img, t[\"vertices\"], t[\"colors\"])\n    return img\n",
        "            img = g_shading(img, t[\"vertices\"], t[\"colors\"])\n"
        "    return (img * 255).astype(np.uint8)\n")
    assert "astype(np.uint8)" in source
    graded = grade_source(tmp_path, source)
    assert [c.id for c in graded.causes] == ["scaled_255"]
    evidence = graded.causes[0].evidence
    assert "up to 255 in" in evidence and "render_img on the probe pairs" in evidence
    assert "probes" not in evidence.replace("probe pairs", "")     # the fills are in [0, 1]
    for t in graded.tests:
        if t.name.startswith(("Hidden scene", "Probes: pairs")):
            assert t.status == "passed", (t.name, t.output)


def test_shading_chosen_by_a_dict_of_other_years_names(tmp_path, sandbox_ok):
    """render_img choosing its fill with `{'flat': f_shading, 'gouraud': g_shading}[shading]`
    (no comparison with a string anywhere): another year's shading values, graded through the
    adapter (a KeyError on 'f' otherwise)."""
    source = INT64_STUDENT.replace(
        """        if shading == "f":
            img = f_shading(img, t["vertices"], t["colors"])
        else:
            img = g_shading(img, t["vertices"], t["colors"])
""", """        shader = {"flat": f_shading, "gouraud": g_shading}[shading]
        img = shader(img, t["vertices"], t["colors"])
""")
    assert "shader = {" in source and 'shading == "f"' not in source
    graded = grade_source(tmp_path, source)
    assert [c.id for c in graded.causes] == ["other_api"]
    assert "with shading 'flat' / 'gouraud'" in graded.causes[0].evidence
    for t in graded.tests:
        if t.name.startswith(("Hidden scene", "Probes: pairs")):    # render_img's tests
            assert t.status == "passed", (t.name, t.output)


def test_face_by_face_tests_undo_the_whole_image_mistakes(tmp_path, sandbox_ok):
    """The course scene face by face through the student's f_shading / g_shading: a transposed
    fill is undone there too (it was compared as it came: every face wrong)."""
    from scantrace.grade import hidden

    scene = hidden.scene(np.random.default_rng(3), n_faces=12)
    sub = write_submission(tmp_path / "student", wrong_source("transposed"))
    graded = grade(sub, tmp_path / "out",
                   dataclasses.replace(quick_options(), scene=course_arrays(scene)))
    assert [c.id for c in graded.causes] == ["transposed"]
    faces = [t for t in graded.tests if t.name.startswith("Course scene face by face")]
    assert len(faces) == 2
    for t in faces:
        assert t.status == "passed", (t.name, t.output)
        assert "after undoing transposed" in t.output


def test_verdicts_are_causes_too(tmp_path, sandbox_ok):
    """A sandbox verdict is a cause of its own (with its sentence and fix, which students see),
    besides the tests' statuses: once per kind, with how many calls ended so."""
    source = CORRECT.replace(
        "def f_shading(img, vertices, vcolors):\n",
        "def f_shading(img, vertices, vcolors):\n    if vertices[0][0] == 2:\n"
        "        while True:\n            pass\n")
    limits = Limits(call_seconds=0.5, batch_seconds=60.0)
    graded = grade_source(tmp_path, source, limits=limits)
    assert [c.id for c in graded.causes] == ["timeout"]
    # The probes whose first vertex has x = 2: general, sliver, long_edges.
    assert sum(p.status == "timeout" for t in graded.tests for p in t.probes) == 3
    cause = graded.causes[0]
    assert "time limit" in cause.sentence and cause.fix
    # And the two calls drawing the pairs' face 0, whose first vertex is (2, 2): the shared edge
    # through f_shading and render_img's pairs.
    assert "(and 4 more calls)" in cause.evidence
    graded = grade_source(tmp_path, "import sys\nsys.exit(3)\n" + CORRECT, name="quitter")
    assert [c.id for c in graded.causes] == ["crashed"]
    assert "sys.exit(3)" in graded.causes[0].sentence


def test_two_copies_of_the_code_are_never_mixed(tmp_path, sandbox_ok):
    """hw1.py beside a notebook export of an older version: all four functions come from one
    module (the one defining the most; ties: the shortest name), said in one note."""
    sub = write_submission(tmp_path / "student", CORRECT)
    write_submission(sub, wrong_source("right_end_excluded"), name="Homework1_notebook.py")
    graded = grade(sub, tmp_path / "out", quick_options())
    assert graded.causes == []
    copies = [n for n in graded.notes if "all are taken from" in n]
    assert len(copies) == 1 and "all are taken from hw1 " in copies[0], graded.notes
    assert "Homework1_notebook" in copies[0]


def test_a_verdict_beyond_the_assignment_is_not_a_cause(tmp_path, sandbox_ok):
    """A loop that never reaches a non-integer end (a Bresenham walk stepping by 1 from 2.5
    towards 18.75) times out on a non-integer probe only: said in its line, not a cause."""
    source = CORRECT.replace(
        "def f_shading(img, vertices, vcolors):\n",
        "def f_shading(img, vertices, vcolors):\n    x, end = vertices[0][0], vertices[1][0]\n"
        "    while x != end:\n        x += 1 if end > x else -1\n")
    graded = grade_source(tmp_path, source, limits=Limits(call_seconds=0.5, batch_seconds=60.0))
    assert graded.causes == []
    outcomes = [p for t in graded.tests for p in t.probes if p.status == "timeout"]
    # (halves: 3.5 + 16 steps reaches 19.5.)
    assert [(p.name, p.integer) for p in outcomes] == [("non_integer", False)]


def test_a_face_with_two_equal_vertices_is_a_probe(tmp_path, sandbox_ok):
    """The seed report's edge table before its fix keeps a zero-length edge (two equal vertices)
    as a vertical one that is never retired, drawing the face as a wedge. The collinear probes
    have three distinct vertices and never show it; a probe with two equal vertices does, with
    no course scene (whose 33 such faces were the only evidence)."""
    equal = [p for p in PROBES if len(set(p.vertices)) < 3]
    assert [p.name for p in equal] == ["zero_length_edge"]
    assert fill_models.degenerate(equal[0].array)
    assert not fill_models.correct(equal[0].array, equal[0].size).any()
    corpus = pathlib.Path(__file__).resolve().parent / "corpus" / "w_seed_zero_length_edge"
    graded = grade(corpus, tmp_path / "out", quick_options())
    assert [c.id for c in graded.causes] == ["degenerate_drawn"]
    assert "probe `zero_length_edge`" in graded.causes[0].evidence


@pytest.mark.parametrize("span,variant", [
    ("range(round(xl), round(xr) + 1)", "round() (halves to even) at both ends, the right end"),
    ("range(int(xl + 0.5), int(xr + 0.5) + 1)", "nearest at both ends, the right end included")])
def test_rounded_span_ends_with_the_right_end_included(tmp_path, sandbox_ok, span, variant):
    """The seed report's literal span loop, `range(round(x1), round(x2) + 1)`: rounded ends and
    the right one filled too. No single axis of the composed models drew it (round() with an
    exclusive end, or the closed rule's ceil/floor), so no cause was named."""
    source = CORRECT.replace("for x in range(math.ceil(xl), math.ceil(xr)):  # SPAN",
                             f"for x in {span}:  # SPAN")
    assert span in source
    graded = grade_source(tmp_path, source)
    assert [c.id for c in graded.causes] == ["span_end_rounding"]
    assert variant in graded.causes[0].sentence
