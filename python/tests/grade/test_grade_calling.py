"""Student code written as the course's students write it, graded through its own functions: it
assumes the course's calling convention (numpy arrays with hw1.npy's dtypes: int64 vertices in
`range()`, `V1 + t * (V2 - V1)` on arrays), keeps edges in dictionaries with active points (as the
real student's report in ../shared/seeds describes), or follows another year's API. Each is held
to full marks on the assignment's domain (the correct ones) or to its cause."""

import textwrap

import numpy as np

from scantrace.grade import diagnose
from scantrace.grade.probes import GOURAUD, PROBES

from conftest import grade_source

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
