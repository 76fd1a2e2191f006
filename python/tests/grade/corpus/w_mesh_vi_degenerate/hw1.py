"""Triangle filling, vectorised with numpy (no python loop over the pixels).

A pixel (x, y) is inside when it is on the inner side of the three edges. Pixels exactly on an
edge are given to the triangle only for its top and left edges (the same rule as D3D/OpenGL), so
that two triangles sharing an edge never paint the same pixel twice.
"""
import numpy as np
import matplotlib
import matplotlib.pyplot as plt


def vector_interp(p1, p2, V1, V2, coord, dim):
    p1, p2 = np.asarray(p1, float), np.asarray(p2, float)
    V1, V2 = np.asarray(V1, float), np.asarray(V2, float)
    t = (coord - p1[dim - 1]) / (p2[dim - 1] - p1[dim - 1])
    return V1 + t * (V2 - V1)


def _coverage(shape, vertices):
    """bounding box origin, boolean mask of the covered pixels and the barycentric weights"""
    v = np.asarray(vertices, dtype=np.float64)
    area = (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) - (v[2, 0] - v[0, 0]) * (v[1, 1] - v[0, 1])
    if area == 0:
        return None
    if area < 0:
        perm = [0, 2, 1]
        v, area = v[perm], -area
    else:
        perm = [0, 1, 2]
    x0 = max(int(np.floor(v[:, 0].min())), 0)
    x1 = min(int(np.ceil(v[:, 0].max())), shape[1] - 1)
    y0 = max(int(np.floor(v[:, 1].min())), 0)
    y1 = min(int(np.ceil(v[:, 1].max())), shape[0] - 1)
    if x1 < x0 or y1 < y0:
        return None
    X, Y = np.meshgrid(np.arange(x0, x1 + 1), np.arange(y0, y1 + 1))
    mask = np.ones(X.shape, dtype=bool)
    w = []
    for a, b in ((1, 2), (2, 0), (0, 1)):
        ex, ey = v[b, 0] - v[a, 0], v[b, 1] - v[a, 1]
        e = ex * (Y - v[a, 1]) - ey * (X - v[a, 0])
        top_left = ey < 0 or (ey == 0 and ex > 0)
        mask &= (e > 0) | ((e == 0) & top_left)
        w.append(e / area)
    weights = np.stack(w, axis=-1)
    # undo the swap of the vertices so that weight k belongs to vertex k
    weights = weights[..., np.argsort(perm)]
    return y0, x0, mask, weights


def f_shading(img, vertices, vcolors):
    cov = _coverage(img.shape, vertices)
    if cov is None:
        return img
    y0, x0, mask, _ = cov
    h, w = mask.shape
    img[y0:y0 + h, x0:x0 + w][mask] = np.mean(vcolors, axis=0)
    return img


def g_shading(img, vertices, vcolors):
    cov = _coverage(img.shape, vertices)
    if cov is None:
        return img
    y0, x0, mask, weights = cov
    h, w = mask.shape
    colours = weights @ np.asarray(vcolors, dtype=np.float64)
    img[y0:y0 + h, x0:x0 + w][mask] = colours[mask]
    return img


def render_img(faces, vertices, vcolors, depth, shading):
    img = np.ones((512, 512, 3))
    order = np.argsort(-np.mean(depth[faces], axis=1), kind="mergesort")
    for f in faces[order]:
        if shading == "f":
            f_shading(img, vertices[f], vcolors[f])
        else:
            g_shading(img, vertices[f], vcolors[f])
    return img


def main():
    data = np.load("hw1.npy", allow_pickle=True).item()
    for shading in ("f", "g"):
        img = render_img(data["faces"], data["vertices"], data["vcolors"], data["depth"], shading)
        plt.imsave(f"{shading}.png", img)


if __name__ == "__main__":
    matplotlib.use("Agg")
    main()
