import numpy as np
import math
import cv2
import matplotlib.pyplot as plt

# the image is changed in place, so the shading functions do not need to return anything


def vector_interp(p1, p2, V1, V2, coord, dim):
    x1, y1 = p1
    x2, y2 = p2
    if dim == 1:
        if x1 == x2:
            return V1
        lam = (x2 - coord) / (x2 - x1)
    else:
        if y1 == y2:
            return V1
        lam = (y2 - coord) / (y2 - y1)
    return lam * np.asarray(V1, dtype=float) + (1 - lam) * np.asarray(V2, dtype=float)


def find_edges(vertices):
    edges = []
    for i in range(3):
        (xa, ya), (xb, yb) = vertices[i], vertices[(i + 1) % 3]
        if ya == yb:
            continue
        if ya < yb:
            edges.append([xa, ya, xb, yb, i, (i + 1) % 3])
        else:
            edges.append([xb, yb, xa, ya, (i + 1) % 3, i])
    return edges


def fill(img, vertices, vcolors, gouraud):
    (xa, ya), (xb, yb), (xc, yc) = vertices
    if (xb - xa) * (yc - ya) == (xc - xa) * (yb - ya):
        return
    edges = find_edges(vertices)
    ymin = math.ceil(min(ya, yb, yc))
    ymax = math.ceil(max(ya, yb, yc))
    flat = [sum(c[k] for c in vcolors) / 3 for k in range(3)]
    for y in range(ymin, ymax):
        points = []
        for x1, y1, x2, y2, i, j in edges:
            if y1 <= y < y2:
                x = x1 + (y - y1) * (x2 - x1) / (y2 - y1)
                c = vector_interp((x1, y1), (x2, y2), vcolors[i], vcolors[j], y, 2)
                points.append((x, c))
        if len(points) != 2:
            continue
        (xl, cl), (xr, cr) = sorted(points, key=lambda p: p[0])
        for x in range(math.ceil(xl), math.ceil(xr)):
            if gouraud:
                img[x][y] = vector_interp((xl, y), (xr, y), cl, cr, x, 1)
            else:
                img[x][y] = flat


def f_shading(img, vertices, vcolors):
    fill(img, vertices, vcolors, False)


def g_shading(img, vertices, vcolors):
    fill(img, vertices, vcolors, True)


def render_img(faces, vertices, vcolors, depth, shading):
    img = np.ones((512, 512, 3))
    face_depth = [sum(depth[k] for k in f) / 3 for f in faces]
    for n in sorted(range(len(faces)), key=lambda n: face_depth[n]):
        tri = [(vertices[k][0], vertices[k][1]) for k in faces[n]]
        cols = [vcolors[k] for k in faces[n]]
        if shading == "f":
            f_shading(img, tri, cols)
        else:
            g_shading(img, tri, cols)
    return img


if __name__ == "__main__":
    data = np.load("hw1.npy", allow_pickle=True).item()
    img = render_img(data["faces"], data["vertices"], data["vcolors"], data["depth"], "g")
    cv2.imwrite("gouraud.png", cv2.cvtColor((img * 255).astype(np.uint8), cv2.COLOR_RGB2BGR))
    plt.imshow(img)
    plt.show()
