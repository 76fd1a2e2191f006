# first version (np.arange spans); kept for reference, hw1.py is the final one
"""Computer Graphics 2024 - Assignment 1 (triangle filling)."""
import numpy as np
import matplotlib.pyplot as plt


def vector_interp(p1, p2, V1, V2, coord, dim):
    p1 = np.asarray(p1, dtype=float)
    p2 = np.asarray(p2, dtype=float)
    V1 = np.asarray(V1, dtype=float)
    V2 = np.asarray(V2, dtype=float)
    i = dim - 1
    if p2[i] == p1[i]:
        return V1
    lam = (coord - p1[i]) / (p2[i] - p1[i])
    return (1 - lam) * V1 + lam * V2


def _crossings(v, y):
    """x of every non horizontal edge that is active on scanline y (half open: top incl.)"""
    xs = []
    for i in range(3):
        a, b = v[i], v[(i + 1) % 3]
        if a[1] == b[1]:
            continue
        if a[1] > b[1]:
            a, b = b, a
        if a[1] <= y < b[1]:
            xs.append(a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
    return xs


def _scan(img, vertices, paint):
    v = np.asarray(vertices, dtype=float)
    area = (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) - (v[2, 0] - v[0, 0]) * (v[1, 1] - v[0, 1])
    if area == 0:
        return img
    H, W = img.shape[:2]
    y0 = max(int(np.ceil(v[:, 1].min())), 0)
    y1 = min(int(np.ceil(v[:, 1].max())), H)
    for y in range(y0, y1):
        xs = _crossings(v, y)
        if len(xs) < 2:
            continue
        xl, xr = min(xs), max(xs)
        cols = np.arange(np.round(xl), np.round(xr)).astype(int)
        cols = cols[(cols >= 0) & (cols < W)]
        if cols.size:
            paint(y, cols, xl, xr)
    return img


def f_shading(img, vertices, vcolors):
    color = np.asarray(vcolors, dtype=float).mean(axis=0)

    def paint(y, cols, xl, xr):
        img[y, cols] = color

    return _scan(img, vertices, paint)


def g_shading(img, vertices, vcolors):
    v = np.asarray(vertices, dtype=float)
    c = np.asarray(vcolors, dtype=float)

    def edge_colour(y, x):
        # colour of the edge whose crossing with row y is x
        for i in range(3):
            a, b = v[i], v[(i + 1) % 3]
            lo, hi = sorted((a[1], b[1]))
            if a[1] != b[1] and lo <= y <= hi:
                xe = a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
                if abs(xe - x) < 1e-9:
                    return vector_interp(a, b, c[i], c[(i + 1) % 3], y, 2)
        raise ValueError("no edge")

    def paint(y, cols, xl, xr):
        cl, cr = edge_colour(y, xl), edge_colour(y, xr)
        t = (cols - xl) / (xr - xl)
        img[y, cols] = np.outer(1 - t, cl) + np.outer(t, cr)

    return _scan(img, vertices, paint)


def render_img(faces, vertices, vcolors, depth, shading):
    M = N = 512
    img = np.ones((M, N, 3))
    faces = np.asarray(faces)
    mean_depth = np.asarray(depth)[faces].mean(axis=1)
    order = np.argsort(-mean_depth, kind="stable")   # far -> near, ties keep their order
    shade = f_shading if shading == "f" else g_shading
    for k in order:
        img = shade(img, vertices[faces[k]], vcolors[faces[k]])
    return img


if __name__ == "__main__":
    data = np.load("hw1.npy", allow_pickle=True).item()
    for s in ("f", "g"):
        im = render_img(data["faces"], data["vertices"], data["vcolors"], data["depth"], s)
        plt.imsave(f"render_{s}.png", np.clip(im, 0, 1))
        plt.imshow(im)
        plt.show()
