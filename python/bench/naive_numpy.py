"""A straightforward pure-numpy version of the course's algorithm, written for the comparison in
bench_render_img.py: what a student's render_img looks like without scantrace.

Per triangle (in painter's order): the scanlines ceil(y_min) .. ceil(y_max) - 1; on each, the
x-intersections of the edges that span the row and their colours (vector_interp along y), then the
pixels ceil(x_left) .. ceil(x_right) - 1 with the colours interpolated along x, written with one
numpy slice assignment per row. It is not meant to match scantrace bit for bit (no fixed-point
snapping); the benchmark checks that it draws nearly the same picture.
"""

import math

import numpy as np


def vector_interp(p1, p2, V1, V2, coord, dim):
    a, b = p1[dim - 1], p2[dim - 1]
    if a == b:
        return (V1 + V2) / 2
    t = (coord - a) / (b - a)
    return V1 + t * (V2 - V1)


def shade_triangle(img, vertices, vcolors, gouraud):
    h, w = img.shape[:2]
    ys = vertices[:, 1]
    y_first = max(math.ceil(ys.min()), 0)
    y_end = min(math.ceil(ys.max()), h)
    flat = vcolors.mean(axis=0)
    edges = [(vertices[i], vertices[(i + 1) % 3], vcolors[i], vcolors[(i + 1) % 3])
             for i in range(3) if vertices[i, 1] != vertices[(i + 1) % 3, 1]]
    for y in range(y_first, y_end):
        points = []
        for p, q, cp, cq in edges:
            lo, hi = min(p[1], q[1]), max(p[1], q[1])
            if lo <= y < hi:
                x = p[0] + (y - p[1]) * (q[0] - p[0]) / (q[1] - p[1])
                points.append((x, vector_interp(p, q, cp, cq, y, 2) if gouraud else None))
        if len(points) < 2:
            continue
        (xl, cl), (xr, cr) = sorted(points, key=lambda pc: pc[0])[:2]
        x0, x1 = max(math.ceil(xl), 0), min(math.ceil(xr), w)
        if x0 >= x1:
            continue
        if gouraud:
            xs = np.arange(x0, x1, dtype=np.float64)
            t = (xs - xl) / (xr - xl) if xr != xl else np.full_like(xs, 0.5)
            img[y, x0:x1] = cl + t[:, None] * (cr - cl)
        else:
            img[y, x0:x1] = flat
    return img


def render_img(faces, vertices, vcolors, depth, shading):
    img = np.ones((512, 512, 3))
    order = np.argsort(-depth[faces].mean(axis=1), kind="stable")
    gouraud = shading in ("g", "gouraud")
    for f in order:
        shade_triangle(img, vertices[faces[f]], vcolors[faces[f]], gouraud)
    return img
