# Graphics HW1 -- scanline fill with an active edge table.
# x is stepped by 1/m from scanline to scanline; to avoid floating point drift
import math

import numpy as np
from tqdm import tqdm


def vector_interp(p1, p2, V1, V2, coord, dim):
    a = p1[dim - 1]
    b = p2[dim - 1]
    if a == b:
        return np.array(V1, dtype=np.float64)
    t = (coord - a) / (b - a)
    return np.array(V1, dtype=np.float64) * (1 - t) + np.array(V2, dtype=np.float64) * t


class ActiveEdge:
    def __init__(self, top, bottom, ctop=None, cbottom=None):
        self.top, self.bottom = top, bottom
        self.ctop, self.cbottom = ctop, cbottom
        y0 = top[1]
        self.ystart = math.ceil(y0)
        self.yend = math.ceil(bottom[1])
        if bottom[0] == top[0]:
            self.inv_m = 0.0      # vertical edge
        else:
            m = (bottom[1] - top[1]) / (bottom[0] - top[0])
            self.inv_m = 1 / m
        self.x = top[0] + (self.ystart - y0) * self.inv_m

    def step(self):
        self.x += self.inv_m


def edge_table(vertices, vcolors):
    v = [(float(p[0]), float(p[1])) for p in vertices]
    et = []
    for i in range(3):
        j = (i + 1) % 3
        if v[i][1] == v[j][1]:
            continue  # horizontal
        if v[i][1] < v[j][1]:
            et.append(ActiveEdge(v[i], v[j], vcolors[i], vcolors[j]))
        else:
            et.append(ActiveEdge(v[j], v[i], vcolors[j], vcolors[i]))
    return et


def scanline(img, vertices, vcolors, put):
    (x0, y0), (x1, y1), (x2, y2) = [(float(p[0]), float(p[1])) for p in vertices]
    if (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0) == 0:
        return img
    et = edge_table(vertices, vcolors)
    first = min(e.ystart for e in et)
    last = max(e.yend for e in et)
    aet = []
    for y in range(first, last):
        aet = [e for e in aet if e.yend > y]
        aet += [e for e in et if e.ystart == y and e.yend > y]
        if len(aet) == 2:
            left, right = sorted(aet, key=lambda e: e.x)
            put(y, left, right)
        for e in aet:
            e.step()
    return img


def f_shading(img, vertices, vcolors):
    color = np.mean(np.array(vcolors, dtype=np.float64), axis=0)

    def put(y, left, right):
        for x in range(math.ceil(left.x), math.ceil(right.x)):
            img[y, x] = color

    return scanline(img, vertices, vcolors, put)


def g_shading(img, vertices, vcolors):
    def put(y, left, right):
        cl = vector_interp(left.top, left.bottom, left.ctop, left.cbottom, y, 2)
        cr = vector_interp(right.top, right.bottom, right.ctop, right.cbottom, y, 2)
        for x in range(math.ceil(left.x), math.ceil(right.x)):
            img[y, x] = vector_interp((float(left.x), y), (float(right.x), y), cl, cr, x, 1)

    return scanline(img, vertices, vcolors, put)


def render_img(faces, vertices, vcolors, depth, shading):
    img = np.ones((512, 512, 3))
    z = np.array([np.mean(depth[f]) for f in faces])
    order = np.argsort(-z, kind="stable")
    fill = {"f": f_shading, "g": g_shading}[shading]
    for i in tqdm(order):
        img = fill(img, vertices[faces[i]], vcolors[faces[i]])
    return img


if __name__ == "__main__":
    import cv2
    data = np.load("hw1.npy", allow_pickle=True).item()
    out = render_img(data["faces"], data["vertices"], data["vcolors"], data["depth"], "f")
    cv2.imwrite("flat.png", (out[:, :, ::-1] * 255).astype(np.uint8))
