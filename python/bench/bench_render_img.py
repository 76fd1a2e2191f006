#!/usr/bin/env python3
"""render_img from Python against the same render in C++, and against a pure-numpy version.

    PYTHONPATH=build/python python3 python/bench/bench_render_img.py [SCENE.json] [--rounds N]
        [--scale K]

Prints medians of N rounds (default 30), the three timed interleaved round by round so that a
busy machine slows them alike, and the median of the per-round ratios (each Python call over the
C++ render of the same round: on a machine whose load swings from round to round, the steadier
figure); the load average is printed. Times are the rendering thread's CPU time by default
(--clock cpu: on two cores shared with other jobs, wall time mostly measures the waits):
  - C++: the library's render of the scene (Image<Rgb32f>, the float canvas of `scantrace
    render`), timed inside C++ (no Python at all);
  - C++ float64: the render that render_img runs (into the recycled float64 image), timed inside
    C++: render_img over it is what Python adds, it over the C++ render what the float64 pixels
    cost (twice the bytes: see docs/performance.md, "render_img and the cache");
  - Python render_img: the course's call, numpy in, a 512 x 512 x 3 float64 image out (the array
    of each round is dropped at once, so the next render reuses its storage, as a loop that
    renders and drops does: course.cpp's RecycledImage);
  - Python render(dtype=float32): the same render into the C++ canvas's own pixel type;
  - pure numpy (naive_numpy.py): a few rounds only, it is slow.
"""

import argparse
import json
import os
import pathlib
import statistics
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import naive_numpy  # noqa: E402
import scantrace  # noqa: E402
from scantrace import _scantrace  # noqa: E402


CLOCKS = {"wall": time.perf_counter, "cpu": time.thread_time}
clock = CLOCKS["cpu"]


def timed(f):
    t0 = clock()
    f()
    return clock() - t0


def main():
    default = pathlib.Path(__file__).resolve().parents[3] / "shared" / "data" / "hw1_2024.json"
    if not default.exists():  # a worktree one level deeper than the clone
        default = pathlib.Path("/work/shared/data/hw1_2024.json")
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scene", nargs="?", default=str(default))
    ap.add_argument("--rounds", type=int, default=30)
    ap.add_argument("--numpy-rounds", type=int, default=3)
    ap.add_argument("--scale", type=float, default=1.0,
                    help="the scene's coordinates and canvas multiplied by K, in (0, 16] (0.5: a "
                         "256 x 256 canvas, whose float64 image fits this machine's 2 MiB L2); "
                         "off 512 x 512, the render_img column is render(size=...) in float64, "
                         "the same C++ render at the other size")
    ap.add_argument("--clock", choices=sorted(CLOCKS), default="cpu",
                    help="cpu (default): the rendering thread's CPU time, user and system "
                         "(time.thread_time; in C++ CLOCK_THREAD_CPUTIME_ID), which leaves out "
                         "the time a render waited for a core on a shared machine; wall: "
                         "elapsed time")
    args = ap.parse_args()
    if not 0 < args.scale <= 16:
        ap.error(f"--scale: expected a factor in (0, 16], got {args.scale:g}")
    global clock
    clock = CLOCKS[args.clock]

    s = scantrace.load_scene(args.scene)
    f, v, c, d = s["faces"], s["vertices"] * args.scale, s["vcolors"], s["depth"]
    size = max(1, round(512 * args.scale))
    with tempfile.TemporaryDirectory() as tmp:
        scene = args.scene
        if args.scale != 1.0:  # the C++ renders read a file: the scaled scene written as one
            scene = os.path.join(tmp, "scaled.json")
            pathlib.Path(scene).write_text(json.dumps(
                {"vertices": v.tolist(), "faces": f.tolist(), "vcolors": c.tolist(),
                 "depth": d.reshape(-1).tolist(), "width": size, "height": size}))
        print(f"{args.scene}: {len(f)} faces, {size} x {size} (scale {args.scale:g}); medians "
              f"of {args.rounds} rounds (numpy: {args.numpy_rounds}); {args.clock} time; load "
              f"average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores\n")
        print("| shading | C++ render | Python render_img (float64) | ratio (of medians / median "
              "of ratios) | C++ float64 (/ C++) | render_img / it | Python render float32 | ratio | "
              "pure numpy | speed-up of render_img |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        for shading in ("f", "g"):
            time_shading(args, scene, (f, v, c, d), size, shading)


def time_shading(args, scene, arrays, size, shading):
    """One row of the table: the renders of one shading interleaved round by round."""
    f, v, c, d = arrays
    cpp, cpp64, py64, py32 = [], [], [], []
    render_img = (lambda: scantrace.render_img(f, v, c, d, shading)) if size == 512 else \
        (lambda: scantrace.render(v, f, c, d, shading=shading, size=(size, size)))
    for _ in range(args.rounds):
        cpp += _scantrace._cpp_render_seconds(scene, shading, 1, args.clock)
        cpp64 += _scantrace._cpp_render_seconds(scene, shading, 1, args.clock, "float64")
        py64.append(timed(render_img))
        py32.append(timed(lambda: scantrace.render(v, f, c, d, shading=shading, size=(size, size),
                                                   dtype=np.float32)))
    clear = [timed(lambda: np.ones((size, size, 3))) for _ in range(args.rounds)]
    naive = []
    for _ in range(args.numpy_rounds if size == 512 else 0):
        naive.append(timed(lambda: naive_numpy.render_img(f, v, c, d, shading)))
    m = {k: statistics.median(x) * 1000 for k, x in
         (("cpp", cpp), ("cpp64", cpp64), ("py64", py64), ("py32", py32))}
    ratio = {k: statistics.median(p / q for p, q in zip(x, y)) for k, x, y in
             (("py64", py64, cpp), ("py64/cpp64", py64, cpp64), ("cpp64", cpp64, cpp),
              ("py32", py32, cpp))}
    naive_cells = "n/a | n/a"
    if naive:
        m["naive"] = statistics.median(naive) * 1000
        naive_cells = f"{m['naive']:.0f} ms | {m['naive'] / m['py64']:.0f}x"
    name = "flat" if shading == "f" else "gouraud"
    print(f"| {name} | {m['cpp']:.2f} ms | {m['py64']:.2f} ms | {m['py64'] / m['cpp']:.2f}x / "
          f"{ratio['py64']:.2f}x | {m['cpp64']:.2f} ms ({ratio['cpp64']:.2f}x) | "
          f"{ratio['py64/cpp64']:.2f}x | "
          f"{m['py32']:.2f} ms | {m['py32'] / m['cpp']:.2f}x / {ratio['py32']:.2f}x | "
          f"{naive_cells} |")
    note = f"np.ones(({size}, {size}, 3)) alone, the float64 image's allocation and clear: " \
           f"{statistics.median(clear) * 1000:.2f} ms"
    if naive:
        ours = scantrace.render_img(f, v, c, d, shading)
        theirs = naive_numpy.render_img(f, v, c, d, shading)
        differ = float((np.abs(ours - theirs) > 1 / 255).any(axis=2).mean())
        note = f"numpy version vs scantrace: {100 * differ:.2f}% of pixels differ by more " \
               f"than one 8-bit level; " + note
    print(f"\n({name}: {note})\n", file=sys.stderr)


if __name__ == "__main__":
    main()
