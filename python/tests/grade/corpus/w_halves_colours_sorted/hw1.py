import math
import numpy as np


def vector_interp(p1, p2, V1, V2, coord, dim):
    if dim not in (1, 2):
        raise ValueError("dim should be 1 or 2")
    d = dim - 1
    if p2[d] - p1[d] == 0:
        return V1
    return np.add(V1, np.multiply((coord - p1[d]) / (p2[d] - p1[d]), np.subtract(V2, V1)))


def _sort_by_y(vertices, vcolors):
    idx = sorted(range(3), key=lambda i: vertices[i][1])
    v = [[float(vertices[i][0]), float(vertices[i][1])] for i in idx]
    c = [np.array(vcolors[i], dtype=float) for i in range(3)]
    return v, c


def _fill_half(img, long_edge, short_edge, y_from, y_to, colour_fn):
    # rows y_from <= y < y_to lie between long_edge and short_edge
    (a, ca, b, cb) = long_edge
    (s, cs, e, ce) = short_edge
    for y in range(math.ceil(y_from), math.ceil(y_to)):
        x1 = vector_interp(a, b, a[0], b[0], y, 2)
        x2 = vector_interp(s, e, s[0], e[0], y, 2)
        c1 = vector_interp(a, b, ca, cb, y, 2)
        c2 = vector_interp(s, e, cs, ce, y, 2)
        if x1 > x2:
            x1, x2, c1, c2 = x2, x1, c2, c1
        for x in range(math.ceil(x1), math.ceil(x2)):
            img[y, x] = colour_fn(x, x1, x2, c1, c2, y)


def _triangle(img, vertices, vcolors, colour_fn):
    (v0, v1, v2), (c0, c1, c2) = _sort_by_y(vertices, vcolors)
    if (v1[0] - v0[0]) * (v2[1] - v0[1]) - (v2[0] - v0[0]) * (v1[1] - v0[1]) == 0:
        return img  # the three points are on a line
    long_edge = (v0, c0, v2, c2)
    if v1[1] > v0[1]:   # upper half (skipped when the top edge is horizontal)
        _fill_half(img, long_edge, (v0, c0, v1, c1), v0[1], v1[1], colour_fn)
    if v2[1] > v1[1]:   # lower half
        _fill_half(img, long_edge, (v1, c1, v2, c2), v1[1], v2[1], colour_fn)
    return img


def f_shading(img, vertices, vcolors):
    flat = np.mean(np.array(vcolors, dtype=float), axis=0)
    return _triangle(img, vertices, vcolors, lambda x, x1, x2, c1, c2, y: flat)


def g_shading(img, vertices, vcolors):
    def gouraud(x, x1, x2, c1, c2, y):
        return vector_interp([x1, y], [x2, y], c1, c2, x, 1)
    return _triangle(img, vertices, vcolors, gouraud)


def render_img(faces, vertices, vcolors, depth, shading):
    img = np.ones((512, 512, 3))
    tri_depth = np.mean(depth[faces], axis=1)
    for k in sorted(range(len(faces)), key=lambda k: tri_depth[k], reverse=True):
        if shading == "f":
            img = f_shading(img, vertices[faces[k]], vcolors[faces[k]])
        elif shading == "g":
            img = g_shading(img, vertices[faces[k]], vcolors[faces[k]])
        else:
            raise ValueError("shading must be 'f' or 'g'")
    return img
