import math
from scanline import edge_list, intersections, rows, is_line


def f_shading(img, vertices, vcolors):
    if is_line(vertices):
        return img
    color = [(vcolors[0][c] + vcolors[1][c] + vcolors[2][c]) / 3 for c in range(3)]
    edges = edge_list(vertices)
    for y in rows(vertices):
        pts = intersections(edges, y)
        if len(pts) < 2:
            continue
        x_left = min(p[0] for p in pts)
        x_right = max(p[0] for p in pts)
        for x in range(math.ceil(x_left), math.ceil(x_right)):
            img[y][x] = color
    return img
