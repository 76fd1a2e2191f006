import math
import numpy as np
from tqdm import tqdm


def vector_interp(p1, p2, V1, V2, coord, dim):
    if dim == 1:
        a, b = p1[0], p2[0]
    else:
        a, b = p1[1], p2[1]
    if a == b:
        return np.array(V1, dtype=float)
    t = (coord - a) / (b - a)
    return (1 - t) * np.array(V1, dtype=float) + t * np.array(V2, dtype=float)


def prepare(vertices):
    # pixel coordinates are integers, so round the vertices first
    v = np.round(np.array(vertices, dtype=float)).astype(int)
    ymin, ymax = v[:, 1].min(), v[:, 1].max()
    edges = []
    for i in range(3):
        j = (i + 1) % 3
        if v[i][1] != v[j][1]:
            top, bot = (i, j) if v[i][1] < v[j][1] else (j, i)
            edges.append((top, bot))
    return v, ymin, ymax, edges


def spans(v, ymin, ymax, edges):
    area = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[2][0] - v[0][0]) * (v[1][1] - v[0][1])
    if area == 0:
        return
    for y in range(ymin, ymax):
        hits = []
        for top, bot in edges:
            (xa, ya), (xb, yb) = v[top], v[bot]
            if ya <= y < yb:
                hits.append((xa + (y - ya) * (xb - xa) / (yb - ya), top, bot))
        hits.sort()
        yield y, hits[0], hits[-1]


def f_shading(img, vertices, vcolors):
    colour = np.mean(vcolors, axis=0)
    for y, left, right in spans(*prepare(vertices)):
        img[y, int(left[0] + 0.5):int(right[0] + 0.5)] = colour
    return img


def g_shading(img, vertices, vcolors):
    v, ymin, ymax, edges = prepare(vertices)
    for y, (xl, t1, b1), (xr, t2, b2) in spans(v, ymin, ymax, edges):
        cl = vector_interp(v[t1], v[b1], vcolors[t1], vcolors[b1], y, 2)
        cr = vector_interp(v[t2], v[b2], vcolors[t2], vcolors[b2], y, 2)
        for x in range(int(xl + 0.5), int(xr + 0.5)):
            img[y, x] = vector_interp([xl, y], [xr, y], cl, cr, x, 1)
    return img


def render_img(faces, vertices, vcolors, depth, shading):
    img = np.ones((512, 512, 3))
    centroid_depth = depth[faces].mean(axis=1)
    order = sorted(range(len(faces)), key=lambda i: centroid_depth[i], reverse=True)
    for i in tqdm(order):
        verts, cols = vertices[faces[i]], vcolors[faces[i]]
        img = f_shading(img, verts, cols) if shading == "f" else g_shading(img, verts, cols)
    return img
