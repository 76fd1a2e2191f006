# Assignment 1: the API as given in the assignment's text
#   interpolate_color(x1, x2, x, C1, C2)
#   shade_triangle(img, verts2d, vcolors, shade_t)   shade_t: 'flat' or 'gouraud'
#   render(verts2d, faces, vcolors, depth, shade_t)
import math
import numpy as np


def interpolate_color(x1, x2, x, C1, C2):
    if x1 == x2:
        return np.array(C1, dtype=float)
    l = (x - x1) / (x2 - x1)
    return (1 - l) * np.array(C1, dtype=float) + l * np.array(C2, dtype=float)


def shade_triangle(img, verts2d, vcolors, shade_t):
    v = np.array(verts2d, dtype=float)
    c = np.array(vcolors, dtype=float)
    if (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) == (v[2, 0] - v[0, 0]) * (v[1, 1] - v[0, 1]):
        return img
    flat = c.mean(axis=0)
    edges = []
    for i in range(3):
        j = (i + 1) % 3
        if v[i, 1] != v[j, 1]:
            edges.append((i, j) if v[i, 1] < v[j, 1] else (j, i))
    for y in range(math.ceil(v[:, 1].min()), math.ceil(v[:, 1].max())):
        act = []
        for i, j in edges:
            if v[i, 1] <= y < v[j, 1]:
                x = v[i, 0] + (y - v[i, 1]) * (v[j, 0] - v[i, 0]) / (v[j, 1] - v[i, 1])
                act.append((x, interpolate_color(v[i, 1], v[j, 1], y, c[i], c[j])))
        if len(act) < 2:
            continue
        (xa, ca), (xb, cb) = sorted(act, key=lambda a: a[0])
        for x in range(math.ceil(xa), math.ceil(xb)):
            if shade_t == "flat":
                img[y, x] = flat
            else:
                img[y, x] = interpolate_color(xa, xb, x, ca, cb)
    return img


def render(verts2d, faces, vcolors, depth, shade_t):
    img = np.ones((512, 512, 3))
    d = np.mean(depth[faces], axis=1)
    for k in np.argsort(-d, kind="stable"):
        img = shade_triangle(img, verts2d[faces[k]], vcolors[faces[k]], shade_t)
    return img
