"""The probe triangles: small canvases, each triangle chosen so that the fill rules and the
mistakes of fill_models.py draw different pixels on at least one of them (tests/grade checks that
every two models differ on some probe). Integer vertices as in the course's scene, and a few
non-integer ones.
"""

import dataclasses

import numpy as np

# Far from white (the blank canvas) in every channel, and different per vertex so a permutation
# of the colours changes every pixel of a Gouraud fill.
COLOURS = np.array([[0.9, 0.1, 0.2], [0.1, 0.7, 0.3], [0.2, 0.3, 0.8]])


@dataclasses.dataclass(frozen=True)
class Probe:
    name: str
    what: str
    vertices: tuple
    size: tuple = (24, 24)     # (height, width)

    @property
    def array(self):
        """The vertices as the course passes them: int64 when they are whole numbers (the dtype of
        the course's hw1.npy, which students' `range(ymin, ymax + 1)` relies on), else float64."""
        return course_vertices(self.vertices)

    @property
    def integer(self):
        """Whole-number vertices, as in the course's scene: the assignment's domain. Probes with
        non-integer vertices are beyond it (graded, reported, never decisive for a cause)."""
        return self.array.dtype == np.int64


def course_vertices(vertices):
    """Vertices with the course's dtype: int64 when every value is a whole number, else float64."""
    array = np.asarray(vertices, dtype=np.float64)
    if array.size and np.all(array == np.round(array)) and np.abs(array).max() < 2 ** 53:
        return array.astype(np.int64)
    return array


PROBES = (
    Probe("general", "a scalene triangle", ((2, 3), (17, 8), (7, 19))),
    Probe("flat_top", "a horizontal top edge", ((3, 4), (18, 4), (9, 16))),
    Probe("flat_bottom", "a horizontal bottom edge", ((10, 3), (3, 17), (19, 17))),
    Probe("vertical_left", "a vertical left edge", ((4, 3), (4, 18), (17, 12))),
    Probe("vertical_right", "a vertical right edge", ((18, 2), (18, 19), (5, 9))),
    Probe("sliver", "a sliver", ((2, 5), (21, 8), (3, 7))),
    Probe("steep", "steep edges", ((11, 1), (14, 22), (8, 15))),
    Probe("long_edges", "long edges of slopes 1/3 and 3/10 (far from their start)",
          ((2, 1), (12, 31), (22, 37)), (40, 40)),
    Probe("border", "a vertex on the canvas corner", ((0, 0), (15, 2), (6, 14))),
    # The canvas's borders in the fill's own terms: a face covering [0, W] x [0, H] fills every
    # pixel exactly once (columns ceil(0) … ceil(W) − 1), so the left and top borders are x = 0
    # and y = 0 and the right and bottom ones x = W and y = H. Each probe below has an edge along
    # one border, so its first or last column or row is filled: a bounds check off by one at
    # either end (fill_models.canvas_border_clipped) leaves it out, and a span or row loop one
    # pixel too long on the right or bottom writes past the canvas.
    Probe("border_left", "a vertical edge on the canvas's left border (x = 0)",
          ((0, 4), (0, 19), (15, 11))),
    Probe("border_top", "a horizontal edge on the canvas's top border (y = 0)",
          ((4, 0), (19, 0), (10, 15))),
    Probe("border_right", "a vertical edge on the canvas's right border (x = 24, the width)",
          ((24, 3), (24, 18), (9, 12))),
    Probe("border_bottom", "a horizontal edge on the canvas's bottom border (y = 24, the height)",
          ((11, 9), (3, 24), (20, 24))),
    Probe("border_corner", "a right angle in the canvas's bottom-right corner (24, 24)",
          ((24, 10), (24, 24), (10, 24))),
    Probe("non_integer", "non-integer vertices", ((2.5, 3.25), (18.75, 9.5), (8.2, 20.6))),
    Probe("halves", "vertices on half pixels", ((3.5, 2.5), (19.5, 10.5), (6.5, 20.5))),
    Probe("zero_area", "a zero-area (collinear) face", ((3, 3), (9, 9), (15, 15))),
    Probe("zero_area_flat", "a zero-area horizontal face", ((3, 8), (12, 8), (18, 8))),
    # Two equal vertices: a zero-length edge, which an edge table keeping `dx == 0` edges as
    # vertical (slope inf) never retires, drawing the face as a wedge; the collinear probes
    # above have three distinct vertices and never show it (the course scene has 33 such faces).
    Probe("zero_length_edge", "a zero-area face with two equal vertices",
          ((3, 3), (3, 3), (15, 12))),
)

# The same triangle with its vertices listed in every order: a Gouraud fill must give the same
# image; colours paired after a sort, or a fixed permutation of the weights, do not.
ORDERS = ((0, 1, 2), (1, 2, 0), (2, 0, 1), (0, 2, 1), (2, 1, 0), (1, 0, 2))
GOURAUD = tuple(
    Probe(f"gouraud_{''.join(map(str, order))}", f"a triangle with its vertices in order {order}",
          tuple(((2, 3), (19, 9), (8, 21))[k] for k in order))
    for order in ORDERS) + (PROBES[1], PROBES[3], PROBES[7])


def _pairs_scene():
    """Pairs of faces for render_img (whose canvas is the course's 512 x 512; the faces lie in its
    top-left corner), each pair separating one rule:
      shared edge: faces 0 and 1 share the diagonal (14, 2)-(2, 14), which passes through pixel
        centres; face 0 is nearer, so it is drawn last, and a closed rule lets it take the
        diagonal's pixels, which the top-left rule gives to face 1 (its left edge);
      tied depths: faces 2 and 3 overlap with equal mean depths: drawn in face order (a stable
        sort), face 3 ends on top;
      distinct depths: faces 4 (farther) and 5 overlap: face 5 ends on top."""
    vertices = np.array([[2, 2], [14, 2], [2, 14], [14, 14],           # the shared edge
                         [20, 2], [36, 4], [22, 18], [26, 6], [40, 10], [30, 22],
                         [2, 20], [18, 22], [6, 36], [8, 24], [22, 28], [12, 40]],
                        dtype=np.int64)
    faces = np.array([[0, 1, 2], [1, 3, 2], [4, 5, 6], [7, 8, 9], [10, 11, 12],
                      [13, 14, 15]], dtype=np.int64)
    face_depth = (4.0, 8.0, 6.0, 6.0, 9.0, 3.0)
    face_colour = ((0.9, 0.2, 0.1), (0.1, 0.6, 0.9), (0.8, 0.7, 0.1), (0.3, 0.1, 0.7),
                   (0.2, 0.8, 0.3), (0.9, 0.4, 0.7))
    depth = np.zeros(len(vertices))
    vcolors = np.zeros((len(vertices), 3))
    for f, face in enumerate(faces):
        for v in face:
            if f != 1 or v == 3:       # the shared vertices keep face 0's depth and colour
                depth[v], vcolors[v] = face_depth[f], face_colour[f]
    # The shared edge's vertices give face 1 a mean depth of (4 + 4 + 8) / 3 > 4: still farther.
    return {"faces": faces, "vertices": vertices, "vcolors": vcolors, "depth": depth}


PAIRS = _pairs_scene()
# The shared edge through f_shading: pairs faces 1 then 0 (the painter's order, face 0 nearer)
# on one blank canvas of SHARED_EDGE_SIZE, as render_img would draw them but without the
# student's sort; each pixel of the diagonal belongs to exactly one face (face 1: its left edge).
SHARED_EDGE_FACES = (1, 0)
SHARED_EDGE_SIZE = (17, 17)
PAIRS_CORNER = 48     # every pair lies in the canvas's top-left 48 x 48 pixels
# Each pair: its name, what it separates, its faces, and the canvas region it lies in (rows,
# columns) where the image is compared.
PAIR_REGIONS = (
    ("shared_edge", "two faces sharing an edge through pixel centres", (0, 1),
     (slice(0, 17), slice(0, 17))),
    ("tied_depths", "two overlapping faces of equal mean depth (drawn in face order)", (2, 3),
     (slice(0, 25), slice(18, 43))),
    ("distinct_depths", "two overlapping faces, the farther drawn first", (4, 5),
     (slice(18, 43), slice(0, 25))),
)
