import numpy as np
import cv2


def vector_interp(p1, p2, V1, V2, coord, dim):
    # dim = 1 -> use x, dim = 2 -> use y
    if dim == 1:
        if p1[0] == p2[0]:
            return V1
        if p1[0] < p2[0]:
            x1, x2, V_left, V_right = p1[0], p2[0], V1, V2
        else:
            x1, x2, V_left, V_right = p2[0], p1[0], V2, V1
        a = (coord - x1) / (x2 - x1)
        return np.add(np.multiply(1 - a, V_left), np.multiply(a, V_right))
    else:
        if p1[1] == p2[1]:
            return V1
        if p1[1] < p2[1]:
            y1, y2, V_down, V_up = p1[1], p2[1], V1, V2
        else:
            y1, y2, V_down, V_up = p2[1], p1[1], V2, V1
        a = (coord - y1) / (y2 - y1)
        return np.add(np.multiply(1 - a, V_down), np.multiply(a, V_up))


def make_edges(vertices, vcolors=None):
    edges = []
    for k in range(3):
        a = vertices[k]
        b = vertices[(k + 1) % 3]
        edge = {
            "name": "Edge " + str(k + 1),
            "x_min": min(a[0], b[0]),
            "x_max": max(a[0], b[0]),
            "y_min": min(a[1], b[1]),
            "y_max": max(a[1], b[1]),
        }
        if a[0] == b[0]:
            edge["slope"] = np.inf
        else:
            edge["slope"] = (b[1] - a[1]) / (b[0] - a[0])
        if vcolors is not None:
            if a[1] > b[1]:
                edge["top_color"], edge["bottom_color"] = vcolors[k], vcolors[(k + 1) % 3]
                edge["top"], edge["bottom"] = a, b
            else:
                edge["top_color"], edge["bottom_color"] = vcolors[(k + 1) % 3], vcolors[k]
                edge["top"], edge["bottom"] = b, a
        edges.append(edge)
    return edges


def update_active_edges(edges, active_edges, y):
    # remove the edges that end at this scanline, add the ones that start here
    active_edges = [e for e in active_edges if e["y_max"] != y]
    for e in edges:
        # horizontal edges (and edges of zero length) never become active
        if e["y_min"] == y and e["y_max"] != e["y_min"]:
            active_edges.append(e)
    return active_edges


def active_point(e, y):
    if e["slope"] == np.inf:
        return e["x_min"]
    if e["slope"] > 0:
        return e["x_min"] + (1 / e["slope"]) * (y - e["y_min"])
    return e["x_max"] + (1 / e["slope"]) * (y - e["y_min"])


def f_shading(img, vertices, vcolors):
    color = np.mean(vcolors, axis=0)
    edges = make_edges(vertices)
    y_min_total = min(e["y_min"] for e in edges)
    y_max_total = max(e["y_max"] for e in edges)
    active_edges = []
    for y in range(y_min_total, y_max_total + 1):
        active_edges = update_active_edges(edges, active_edges, y)
        active_points = []
        for e in active_edges:
            active_points.append([active_point(e, y), y])
        if len(active_points) < 2:
            continue
        active_points.sort(key=lambda p: p[0])
        for x in range(round(active_points[0][0]), round(active_points[1][0]) + 1):
            img[y, x] = color
    return img


def g_shading(img, vertices, vcolors):
    edges = make_edges(vertices, vcolors)
    y_min_total = min(e["y_min"] for e in edges)
    y_max_total = max(e["y_max"] for e in edges)
    active_edges = []
    for y in range(y_min_total, y_max_total + 1):
        active_edges = update_active_edges(edges, active_edges, y)
        active_points_colors = []
        for e in active_edges:
            x = active_point(e, y)
            c = vector_interp(e["bottom"], e["top"], e["bottom_color"], e["top_color"], y, 2)
            active_points_colors.append([[x, y], c])
        if len(active_points_colors) < 2:
            continue
        active_points_colors.sort(key=lambda p: p[0][0])
        (p1, c1), (p2, c2) = active_points_colors[0], active_points_colors[1]
        for x in range(round(p1[0]), round(p2[0]) + 1):
            img[y, x] = vector_interp(p1, p2, c1, c2, x, 1)
    return img


def render_img(faces, vertices, vcolors, depth, shading):
    img = np.ones((512, 512, 3))
    triangles = []
    for face in faces:
        triangle = {
            "vertices": vertices[face],
            "color": vcolors[face],
            "depth": np.mean(depth[face]),
        }
        triangles.append(triangle)
    triangles = sorted(triangles, key=lambda t: t["depth"], reverse=True)
    for t in triangles:
        if shading == "f":
            img = f_shading(img, t["vertices"], t["color"])
        elif shading == "g":
            img = g_shading(img, t["vertices"], t["color"])
    return img
