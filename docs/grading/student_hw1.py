"""A student's hw1 (the example of docs/grading.md): two mistakes a grader meets every year —
the span's last pixel left out, and faces of equal depth drawn the wrong way round."""

import math
import numpy as np
import matplotlib.pyplot as plt
from tqdm import tqdm


def vector_interp(p1, p2, V1, V2, coord, dim):
    a, b = p1[dim - 1], p2[dim - 1]
    if a == b:  # DEGENERATE_VI
        return np.asarray(V1, dtype=float)
    t = (coord - a) / (b - a)
    return (1 - t) * np.asarray(V1, dtype=float) + t * np.asarray(V2, dtype=float)


def _area2(v):
    return (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[2][0] - v[0][0]) * (v[1][1] - v[0][1])


def _edges(vertices):
    edges = []
    for i in range(3):
        a, b = vertices[i], vertices[(i + 1) % 3]
        if a[1] == b[1]:
            continue
        if a[1] > b[1]:
            a, b = b, a
        edges.append((a, b))
    return edges


def _put(img, x, y, colour):
    if 0 <= x < img.shape[1] and 0 <= y < img.shape[0]:
        img[y, x] = colour  # PUT


def _fill(img, vertices, colour_at):
    vertices = np.asarray(vertices, dtype=float)
    if _area2(vertices) == 0:
        return img  # DEGENERATE
    ymin, ymax = vertices[:, 1].min(), vertices[:, 1].max()
    edges = _edges(vertices)
    for y in range(math.ceil(ymin), math.ceil(ymax)):  # ROWS
        xs = []
        for a, b in edges:
            if a[1] <= y < b[1]:  # ACTIVE
                xs.append(a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))  # CROSSING
        if len(xs) < 2:
            continue
        xl, xr = min(xs), max(xs)
        for x in range(math.ceil(xl), math.floor(xr)):
            _put(img, x, y, colour_at(x, y))
    return img


def f_shading(img, vertices, vcolors):
    colour = np.mean(np.asarray(vcolors, dtype=float), axis=0)  # FLAT
    return _fill(img, vertices, lambda x, y: colour)


def g_shading(img, vertices, vcolors):
    v = np.asarray(vertices, dtype=float)
    c = np.asarray(vcolors, dtype=float)  # COLOURS
    if _area2(v) == 0:
        return img
    m = np.array([[v[0, 0], v[1, 0], v[2, 0]], [v[0, 1], v[1, 1], v[2, 1]], [1, 1, 1]])
    inv = np.linalg.inv(m)
    return _fill(img, vertices, lambda x, y: (inv @ [x, y, 1]) @ c)


def render_img(faces, vertices, vcolors, depth, shading):
    img = np.ones((512, 512, 3))  # CANVAS
    depth = np.asarray(depth, dtype=float).reshape(-1)
    order = np.argsort(depth[faces].mean(axis=1))[::-1]
    for k in tqdm(order):
        face = faces[k]
        if shading == "f":
            f_shading(img, vertices[face], vcolors[face])
        else:
            g_shading(img, vertices[face], vcolors[face])
    return img  # RETURN


data = np.load("/home/student/hw1.npy", allow_pickle=True).item()
plt.imshow(render_img(data["faces"], data["vertices"], data["vcolors"], data["depth"], "f"))
plt.show()
