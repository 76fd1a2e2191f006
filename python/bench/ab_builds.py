#!/usr/bin/env python3
"""Two builds of the module compared on the course scene, old and new alternated in one run.

    python3 python/bench/ab_builds.py OLD_DIR NEW_DIR [SCENE.json] [--rounds N] [--batch K]

OLD_DIR and NEW_DIR each hold a `scantrace/` package (a copy of build/python/scantrace made
before and after a change). Two builds of a pybind11 module cannot live in one process (they
register the same C++ types), so each round starts one process per build, in alternate order;
a process times K renders of each kind and reports their median. Printed per build and shading:
the median over the rounds of the CPU time of this thread (time.thread_time and
CLOCK_THREAD_CPUTIME_ID: the time a render waited for a core on a shared machine does not
count) for the C++ render (the library's Image<Rgb32f>, timed inside C++),
of render_img (float64) and of render(dtype=float32), and the median of the per-round ratios
render_img / C++ (the steadier figure on a machine whose load swings). The load average is
printed before and after: the two cores are often shared. Last, per shading, the median of
the per-round ratios new / old (the two processes of a round ran back to back).
"""

import argparse
import json
import os
import pathlib
import statistics
import subprocess
import sys

CHILD = r"""
import json, statistics, sys, time
import numpy as np
import scantrace
from scantrace import _scantrace
path, batch = sys.argv[1], int(sys.argv[2])
s = scantrace.load_scene(path)
f, v, c, d = s["faces"], s["vertices"], s["vcolors"], s["depth"]
def timed(fn):
    t0 = time.thread_time(); fn(); return time.thread_time() - t0
out = {}
for shading in ("f", "g"):
    cpp, py64, py32 = [], [], []
    for _ in range(batch):
        cpp += _scantrace._cpp_render_seconds(path, shading, 1, "cpu")
        py64.append(timed(lambda: scantrace.render_img(f, v, c, d, shading)))
        py32.append(timed(lambda: scantrace.render(v, f, c, d, shading=shading,
                                                   dtype=np.float32)))
    out[shading] = {k: statistics.median(x) for k, x in
                    (("cpp", cpp), ("py64", py64), ("py32", py32))}
    out[shading]["ratio"] = statistics.median(p / q for p, q in zip(py64, cpp))
print(json.dumps(out))
"""


def run(build, scene, batch):
    env = dict(os.environ, PYTHONPATH=str(build))
    r = subprocess.run([sys.executable, "-c", CHILD, scene, str(batch)], env=env,
                       capture_output=True, text=True, check=True)
    return json.loads(r.stdout)


def main():
    default = pathlib.Path("/work/shared/data/hw1_2024.json")
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("scene", nargs="?", default=str(default))
    ap.add_argument("--rounds", type=int, default=10)
    ap.add_argument("--batch", type=int, default=20)
    args = ap.parse_args()
    for d in (args.old, args.new):
        if not (pathlib.Path(d) / "scantrace").is_dir():
            sys.exit(f"{d}: no scantrace/ package in it")
    load0 = os.getloadavg()[0]
    results = {"old": [], "new": []}
    for i in range(args.rounds):
        order = ("old", "new") if i % 2 == 0 else ("new", "old")
        for which in order:
            results[which].append(run(getattr(args, which), args.scene, args.batch))
    print(f"{args.scene}: {args.rounds} rounds of {args.batch} renders per build, alternated; "
          f"load average {load0:.2f} before, {os.getloadavg()[0]:.2f} after, on "
          f"{os.cpu_count()} cores\n")
    print("| build | shading | C++ render ms | render_img ms | render float32 ms | "
          "render_img / C++ (median of ratios) |")
    print("|---|---|---:|---:|---:|---:|")
    for which in ("old", "new"):
        for shading in ("f", "g"):
            m = {k: statistics.median(r[shading][k] for r in results[which])
                 for k in ("cpp", "py64", "py32", "ratio")}
            print(f"| {which} | {'flat' if shading == 'f' else 'gouraud'} | "
                  f"{m['cpp'] * 1000:.3f} | {m['py64'] * 1000:.3f} | {m['py32'] * 1000:.3f} | "
                  f"{m['ratio']:.3f} |")
    # The two processes of a round ran back to back: their ratio cancels most of the load's swing.
    print("\nnew / old, median of the per-round ratios (the two builds of a round ran back to back):")
    for shading in ("f", "g"):
        pairs = list(zip(results["old"], results["new"]))
        print(f"  {'flat' if shading == 'f' else 'gouraud'}: " + ", ".join(
            f"{k} {statistics.median(n[shading][k] / o[shading][k] for o, n in pairs):.3f}"
            for k in ("cpp", "py64", "py32")))


if __name__ == "__main__":
    main()
