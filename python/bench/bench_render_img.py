#!/usr/bin/env python3
"""render_img from Python against the same render in C++, and against a pure-numpy version.

    PYTHONPATH=build/python python3 python/bench/bench_render_img.py [SCENE.json] [--rounds N]

Prints medians of N rounds (default 30), the three timed interleaved round by round so that a
busy machine slows them alike, and the median of the per-round ratios (each Python call over the
C++ render of the same round: on a machine whose load swings from round to round, the steadier
figure); the load average is printed. Times are the rendering thread's CPU time by default
(--clock cpu: on two cores shared with other jobs, wall time mostly measures the waits):
  - C++: the library's render of the scene (Image<Rgb32f>, the float canvas of `scantrace
    render`), timed inside C++ (no Python at all);
  - Python render_img: the course's call, numpy in, a 512 x 512 x 3 float64 image out (the array
    of each round is dropped at once, so the next render reuses its storage, as a loop that
    renders and drops does: course.cpp's RecycledImage);
  - Python render(dtype=float32): the same render into the C++ canvas's own pixel type;
  - pure numpy (naive_numpy.py): a few rounds only, it is slow.
"""

import argparse
import os
import pathlib
import statistics
import sys
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
    ap.add_argument("--clock", choices=sorted(CLOCKS), default="cpu",
                    help="cpu (default): the rendering thread's CPU time, user and system "
                         "(time.thread_time; in C++ CLOCK_THREAD_CPUTIME_ID), which leaves out "
                         "the time a render waited for a core on a shared machine; wall: "
                         "elapsed time")
    args = ap.parse_args()
    global clock
    clock = CLOCKS[args.clock]

    s = scantrace.load_scene(args.scene)
    f, v, c, d = s["faces"], s["vertices"], s["vcolors"], s["depth"]
    print(f"{args.scene}: {len(f)} faces; medians of {args.rounds} rounds (numpy: "
          f"{args.numpy_rounds}); {args.clock} time; load average {os.getloadavg()[0]:.2f} on "
          f"{os.cpu_count()} cores\n")
    print("| shading | C++ render | Python render_img (float64) | ratio (of medians / median of "
          "ratios) | Python render float32 | ratio | pure numpy | speed-up of render_img |")
    print("|---|---|---|---|---|---|---|---|")
    for shading in ("f", "g"):
        cpp, py64, py32 = [], [], []
        for _ in range(args.rounds):
            cpp += _scantrace._cpp_render_seconds(args.scene, shading, 1, args.clock)
            py64.append(timed(lambda: scantrace.render_img(f, v, c, d, shading)))
            py32.append(timed(lambda: scantrace.render(v, f, c, d, shading=shading,
                                                       dtype=np.float32)))
        clear = [timed(lambda: np.ones((512, 512, 3))) for _ in range(args.rounds)]
        naive = []
        for _ in range(args.numpy_rounds):
            naive.append(timed(lambda: naive_numpy.render_img(f, v, c, d, shading)))
        ours = scantrace.render_img(f, v, c, d, shading)
        theirs = naive_numpy.render_img(f, v, c, d, shading)
        differ = float((np.abs(ours - theirs) > 1 / 255).any(axis=2).mean())
        m = {k: statistics.median(x) * 1000 for k, x in
             (("cpp", cpp), ("py64", py64), ("py32", py32), ("naive", naive))}
        r64 = statistics.median(p / q for p, q in zip(py64, cpp))
        r32 = statistics.median(p / q for p, q in zip(py32, cpp))
        print(f"| {'flat' if shading == 'f' else 'gouraud'} | {m['cpp']:.2f} ms | "
              f"{m['py64']:.2f} ms | {m['py64'] / m['cpp']:.2f}x / {r64:.2f}x | "
              f"{m['py32']:.2f} ms | {m['py32'] / m['cpp']:.2f}x / {r32:.2f}x | "
              f"{m['naive']:.0f} ms | {m['naive'] / m['py64']:.0f}x |")
        print(f"\n({'flat' if shading == 'f' else 'gouraud'}: numpy version vs scantrace: "
              f"{100 * differ:.2f}% of pixels differ by more than one 8-bit level; "
              f"np.ones((512, 512, 3)) alone, the float64 image's allocation and clear: "
              f"{statistics.median(clear) * 1000:.2f} ms)\n", file=sys.stderr)


if __name__ == "__main__":
    main()
