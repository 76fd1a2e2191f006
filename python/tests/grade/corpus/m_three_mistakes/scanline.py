import math


def edge_list(vertices):
    """The three edges as (x1, y1, x2, y2) with y1 <= y2, and the indices of their vertices."""
    out = []
    for i, j in ((0, 1), (1, 2), (2, 0)):
        x1, y1 = vertices[i][0], vertices[i][1]
        x2, y2 = vertices[j][0], vertices[j][1]
        if y1 > y2:
            out.append(((x2, y2, x1, y1), (j, i)))
        else:
            out.append(((x1, y1, x2, y2), (i, j)))
    return out


def intersections(edges, y):
    """Intersections of scanline y with the edges: a list of (x, edge index)."""
    pts = []
    for n, ((x1, y1, x2, y2), _) in enumerate(edges):
        if y1 == y2:          # horizontal: the other two edges give its end points
            continue
        if y1 <= y < y2:
            pts.append((x1 + (x2 - x1) * (y - y1) / (y2 - y1), n))
    return pts


def rows(vertices):
    ys = [v[1] for v in vertices]
    return range(math.ceil(min(ys)), math.ceil(max(ys)))


def is_line(vertices):
    (x0, y0), (x1, y1), (x2, y2) = [(v[0], v[1]) for v in vertices]
    return (x1 - x0) * (y2 - y0) == (x2 - x0) * (y1 - y0)
