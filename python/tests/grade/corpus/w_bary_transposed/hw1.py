import numpy as np
from tqdm import tqdm


def vector_interp(p1, p2, V1, V2, coord, dim):
    if dim == 1:
        c1, c2 = p1[0], p2[0]
    elif dim == 2:
        c1, c2 = p1[1], p2[1]
    else:
        raise ValueError("dim must be 1 or 2")
    if c1 == c2:
        return V1
    t = (coord - c1) / (c2 - c1)
    return V1 + t * (V2 - V1)


def edge_fn(a, b, p):
    # > 0 when p is on the left of a->b (y axis pointing down)
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def owns_edge(a, b):
    # top-left rule: a pixel centre that lies exactly on an edge belongs to the triangle
    # only if the edge is a left edge or a top (horizontal) edge
    dx = b[0] - a[0]
    dy = b[1] - a[1]
    return dy < 0 or (dy == 0 and dx > 0)


def raster(img, vertices, shade):
    v = [(float(p[0]), float(p[1])) for p in vertices]
    area = edge_fn(v[0], v[1], v[2])
    if area == 0:
        return img
    if area < 0:                       # make it counter clockwise (in y-down coordinates)
        v = [v[0], v[2], v[1]]
        area = -area
        shade = shade[1]
    else:
        shade = shade[0]
    h, w = img.shape[0], img.shape[1]
    xmin = max(int(np.floor(min(p[0] for p in v))), 0)
    xmax = min(int(np.ceil(max(p[0] for p in v))), w - 1)
    ymin = max(int(np.floor(min(p[1] for p in v))), 0)
    ymax = min(int(np.ceil(max(p[1] for p in v))), h - 1)
    edges = [(v[1], v[2]), (v[2], v[0]), (v[0], v[1])]
    tl = [owns_edge(a, b) for a, b in edges]
    for y in range(ymin, ymax + 1):
        for x in range(xmin, xmax + 1):
            ws = [edge_fn(a, b, (x, y)) for a, b in edges]
            inside = True
            for wk, ok in zip(ws, tl):
                if wk < 0 or (wk == 0 and not ok):
                    inside = False
                    break
            if inside:
                img[x, y] = shade(ws[0] / area, ws[1] / area, ws[2] / area)
    return img


def f_shading(img, vertices, vcolors):
    colour = np.array(vcolors, dtype=float).mean(axis=0)
    flat = lambda l0, l1, l2: colour
    return raster(img, vertices, (flat, flat))


def g_shading(img, vertices, vcolors):
    c = np.array(vcolors, dtype=float)
    # when the vertices are swapped to make the triangle ccw the colours swap with them
    ccw = lambda l0, l1, l2: l0 * c[0] + l1 * c[1] + l2 * c[2]
    cw = lambda l0, l1, l2: l0 * c[0] + l1 * c[2] + l2 * c[1]
    return raster(img, vertices, (ccw, cw))


def render_img(faces, vertices, vcolors, depth, shading):
    img = np.ones((512, 512, 3))
    d = [np.mean(depth[f]) for f in faces]
    order = sorted(range(len(faces)), key=lambda k: d[k], reverse=True)
    for k in tqdm(order, desc="render"):
        f = faces[k]
        if shading == "f":
            img = f_shading(img, vertices[f], vcolors[f])
        else:
            img = g_shading(img, vertices[f], vcolors[f])
    return img
