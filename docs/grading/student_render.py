#!/usr/bin/env python3
"""A student-style flat renderer of the course scene, with three mistakes real submissions make:

1. the canvas is indexed img[x][y] (transposed);
2. span ends are rounded to the nearest integer instead of ceil(x_L) .. ceil(x_R) - 1;
3. an edge with y1 == y2 is skipped to avoid a division by zero, and with it every face that has
   a horizontal edge.

    student_render.py SCENE.json OUT.npy

Used for the worked example of docs/grading.md (scantrace diff SCENE OUT.npy --shading flat).
"""
import json
import math
import sys

import numpy as np


def main():
    scene = json.load(open(sys.argv[1]))
    v = np.array(scene["vertices"], dtype=float)
    c = np.array(scene["vcolors"], dtype=float)
    faces = np.array(scene["faces"], dtype=int)
    depth = np.array(scene["depth"], dtype=float)
    h, w = scene.get("height", 512), scene.get("width", 512)
    img = np.ones((h, w, 3), dtype=np.float32)
    order = np.argsort(-depth[faces].mean(axis=1), kind="stable")
    for f in order:
        p = v[faces[f]]
        if any(p[i][1] == p[(i + 1) % 3][1] for i in range(3)):
            continue  # "division by zero": the face is lost
        colour = c[faces[f]].mean(axis=0)
        y0, y1 = math.ceil(p[:, 1].min()), math.ceil(p[:, 1].max())
        for y in range(max(y0, 0), min(y1, h)):
            xs = []
            for i in range(3):
                a, b = p[i], p[(i + 1) % 3]
                if min(a[1], b[1]) <= y <= max(a[1], b[1]):
                    xs.append(a[0] + (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]))
            if len(xs) < 2:
                continue
            for x in range(max(round(min(xs)), 0), min(round(max(xs)), w - 1) + 1):
                img[x][y] = colour  # img[x][y]: transposed
    np.save(sys.argv[2], img)


main()
