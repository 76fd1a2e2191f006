import math
import numpy as np
from shapes import Triangle


def vector_interp(p1, p2, V1, V2, coord, dim):
    i = 0 if dim == 1 else 1
    V1 = np.asarray(V1, dtype=float)
    V2 = np.asarray(V2, dtype=float)
    if p1[i] == p2[i]:
        return (V1 + V2) / 2
    w = (coord - p1[i]) / (p2[i] - p1[i])
    return V1 + w * (V2 - V1)


def f_shading(img, vertices, vcolors):
    out = img.copy()
    tri = Triangle(vertices, vcolors)
    if tri.degenerate():
        return out
    colour = np.asarray(vcolors, dtype=float).mean(axis=0)
    for y, _, xl, _, xr in tri.scanlines():
        out[y, math.floor(xl):math.floor(xr)] = colour
    return out


def g_shading(img, vertices, vcolors):
    out = img.copy()
    tri = Triangle(vertices, vcolors)
    if tri.degenerate():
        return out
    for y, el, xl, er, xr in tri.scanlines():
        cl = vector_interp(el.p, el.q, el.cp, el.cq, y, 2)
        cr = vector_interp(er.p, er.q, er.cp, er.cq, y, 2)
        for x in range(math.floor(xl), math.floor(xr)):
            out[y, x] = vector_interp((xl, y), (xr, y), cl, cr, x, 1)
    return out


class Face:
    def __init__(self, index, depth):
        self.index = index
        self.depth = depth


def render_img(faces, vertices, vcolors, depth, shading):
    canvas = np.ones((512, 512, 3))
    order = [Face(i, float(np.mean(depth[f]))) for i, f in enumerate(faces)]
    order.sort(key=lambda face: face.depth, reverse=True)   # painter: far ones first
    shader = f_shading if shading == "f" else g_shading
    for face in order:
        idx = faces[face.index]
        canvas = shader(canvas, vertices[idx], vcolors[idx])
    return canvas
