#!/usr/bin/env python3
"""What a Python user would use instead of scantrace to fill the course scene's triangles, timed in
the same run as scantrace's render and as a diff from Python, with each one's pixel differences
from the exact render.

    PYTHONPATH=build/python python3 python/bench/bench_alternatives.py [SCENE] [--rounds N]

The alternatives draw each face in the painter's order (deepest first, as the course asks) in its
flat colour (the mean of its vertex colours, as 8-bit), on white:
  - cv2.fillConvexPoly (Debian's python3-opencv), integer vertices;
  - skimage.draw.polygon (python3-skimage), rows and columns of the pixels inside;
  - PIL.ImageDraw.polygon (python3-pil).
An alternative whose module is not installed is listed as such. Differences are counted against
scantrace's flat render in 8 bits, under its default top-left rule and under the closed rule (a
pixel whose centre is on an edge is drawn: what the course's own code and OpenCV do), as pixels
whose colour differs by more than one level. Times are medians of N rounds, every contender timed
once per round in turn, so that a busy machine slows them alike; the load average is printed.
"""

import argparse
import os
import pathlib
import statistics
import time

import numpy as np

import scantrace


def painter_order(faces, depth):
    """Deepest first, ties in face order (the course's painter's order)."""
    mean = depth[faces].mean(axis=1)
    return np.argsort(-mean, kind="stable")


def flat_colours(faces, vcolors):
    return np.clip(np.round(255 * vcolors[faces].mean(axis=1)), 0, 255).astype(np.uint8)


def with_cv2(faces, vertices, order, colours, size):
    import cv2
    img = np.full((size[1], size[0], 3), 255, np.uint8)
    pts = np.round(vertices).astype(np.int32)
    for f in order:
        cv2.fillConvexPoly(img, pts[faces[f]], colours[f].tolist())
    return img


def with_skimage(faces, vertices, order, colours, size):
    from skimage.draw import polygon
    img = np.full((size[1], size[0], 3), 255, np.uint8)
    for f in order:
        v = vertices[faces[f]]
        rr, cc = polygon(v[:, 1], v[:, 0], shape=img.shape[:2])
        img[rr, cc] = colours[f]
    return img


def with_pil(faces, vertices, order, colours, size):
    from PIL import Image, ImageDraw
    img = Image.new("RGB", size, (255, 255, 255))
    draw = ImageDraw.Draw(img)
    for f in order:
        draw.polygon([tuple(p) for p in vertices[faces[f]].tolist()], fill=tuple(colours[f].tolist()))
    return np.asarray(img)


ALTERNATIVES = {"cv2.fillConvexPoly": ("cv2", with_cv2),
                "skimage.draw.polygon": ("skimage", with_skimage),
                "PIL.ImageDraw.polygon": ("PIL", with_pil)}


def available(module):
    try:
        __import__(module)
        return True
    except ImportError:
        return False


def differing(a, b):
    return int((np.abs(a.astype(int) - b.astype(int)) > 1).any(axis=2).sum())


def main():
    default = pathlib.Path(__file__).resolve().parents[3] / "shared" / "data" / "hw1_2024.json"
    if not default.exists():  # a worktree one level deeper than the clone
        default = pathlib.Path("/work/shared/data/hw1_2024.json")
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scene", nargs="?", default=str(default))
    ap.add_argument("--rounds", type=int, default=11)
    args = ap.parse_args()

    s = scantrace.load_scene(args.scene)
    f, v, c, d = s["faces"], s["vertices"], s["vcolors"], s["depth"]
    size = s["size"]
    order, colours = painter_order(f, d), flat_colours(f, c)
    exact = {rule: scantrace.render(**s, shading="flat", fill_rule=rule, dtype=np.uint8)
             for rule in ("top-left", "closed")}
    contenders = {"scantrace.render (flat, float64)":
                  lambda: scantrace.render(**s, shading="flat"),
                  "scantrace.render_img (course call, flat)":
                  lambda: scantrace.render_img(f, v, c, d, "f")}
    for name, (module, draw) in ALTERNATIVES.items():
        if available(module):
            contenders[name] = lambda draw=draw: draw(f, v, order, colours, size)
    # A student's flat render with mistakes (every 37th row grey), for the diff's timing: against
    # the flat reference (the pixels of those rows differ), and against the Gouraud one (every
    # pixel of every face differs: the most a diff of this scene classifies).
    student = scantrace.render_img(f, v, c, d, "f")
    student[::37] = 0.5
    contenders["scantrace.diff (flat image with grey rows, flat reference)"] = \
        lambda: scantrace.diff(s, student, shading="flat")
    contenders["scantrace.diff (the same image, Gouraud reference)"] = \
        lambda: scantrace.diff(s, student, shading="gouraud")
    # The Gouraud assignment's own case: a Gouraud render with the same grey rows against the
    # Gouraud reference.
    student_g = scantrace.render_img(f, v, c, d, "g")
    student_g[::37] = 0.5
    contenders["scantrace.diff (Gouraud image with grey rows, Gouraud reference)"] = \
        lambda: scantrace.diff(s, student_g, shading="gouraud")
    times = {name: [] for name in contenders}
    cpp_times = []
    for _ in range(args.rounds):
        # The C++ render too, in every round (timed inside C++), so that load slows all alike.
        cpp_times += scantrace._scantrace._cpp_render_seconds(args.scene, "flat", 1)
        for name, run in contenders.items():
            t0 = time.perf_counter()
            run()
            times[name].append(time.perf_counter() - t0)
    cpp = statistics.median(cpp_times)
    print(f"{args.scene}: {len(f)} faces, {size[0]}x{size[1]}; medians of {args.rounds} rounds; "
          f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores\n")
    print("| what | ms | pixels differing from the exact render (top-left / closed rule) |")
    print("|---|---:|---|")
    print(f"| C++ render (scantrace's library, flat, float canvas) | {cpp * 1000:.2f} | 0 / — |")
    for name, run in contenders.items():
        ms = statistics.median(times[name]) * 1000
        if name.startswith("scantrace.diff"):
            print(f"| {name} | {ms:.1f} | — |")
            continue
        img = run()
        if img.dtype != np.uint8:
            img = np.round(np.asarray(img) * 255).astype(np.uint8)
        print(f"| {name} | {ms:.2f} | {differing(img, exact['top-left'])} / "
              f"{differing(img, exact['closed'])} |")
    for name, (module, _) in ALTERNATIVES.items():
        if not available(module):
            print(f"| {name} | not installed ({module}) | — |")


if __name__ == "__main__":
    main()
