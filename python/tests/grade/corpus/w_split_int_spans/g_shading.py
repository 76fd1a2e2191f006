import math
from scanline import edge_list, intersections, rows, is_line
from vector_interp import vector_interp


def g_shading(img, vertices, vcolors):
    if is_line(vertices):
        return img
    edges = edge_list(vertices)
    for y in rows(vertices):
        pts = intersections(edges, y)
        if len(pts) < 2:
            continue
        cols = []
        for x, n in pts:
            (x1, y1, x2, y2), (i, j) = edges[n]
            cols.append((x, vector_interp((x1, y1), (x2, y2), vcolors[i], vcolors[j], y, 2)))
        left = min(cols, key=lambda p: p[0])
        right = max(cols, key=lambda p: p[0])
        for x in range(int(left[0]), int(right[0])):
            img[y][x] = vector_interp((left[0], y), (right[0], y), left[1], right[1], x, 1)
    return img
