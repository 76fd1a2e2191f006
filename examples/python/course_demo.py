#!/usr/bin/env python3
"""The course's demo_f.py and demo_g.py done with scantrace: load a scene, render it flat and
Gouraud with render_img, save the images.

    python3 examples/python/course_demo.py [SCENE.json|SCENE.npy] [OUT_DIR]

SCENE defaults to the course scene ../shared/data/hw1_2024.json; a .npy file holding the course's
dict (vertices, vcolors, faces, depth) is read too.
"""

import pathlib
import sys
import time

import numpy as np

import scantrace


def load(path):
    if path.suffix == ".npy":  # the course's format: a pickled dict in a .npy file
        data = np.load(path, allow_pickle=True).tolist()
        return data["faces"], data["vertices"], data["vcolors"], data["depth"]
    scene = scantrace.load_scene(path)
    return scene["faces"], scene["vertices"], scene["vcolors"], scene["depth"]


def main():
    here = pathlib.Path(__file__).resolve().parent
    scene_path = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else (
        here.parents[2] / "shared" / "data" / "hw1_2024.json")
    out_dir = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else pathlib.Path(".")
    out_dir.mkdir(parents=True, exist_ok=True)
    faces, vertices, vcolors, depth = load(scene_path)
    for shading, name in (("f", "flat"), ("g", "gouraud")):
        t0 = time.perf_counter()
        img = scantrace.render_img(faces, vertices, vcolors, depth, shading)
        ms = 1000 * (time.perf_counter() - t0)
        out = out_dir / f"render_{name}.png"
        scantrace.write_png(img, out)
        drawn = int((img != 1).any(axis=2).sum())
        print(f"{scene_path.name}: {len(faces)} faces, {name}: {drawn} pixels drawn "
              f"in {ms:.1f} ms -> {out}")


if __name__ == "__main__":
    main()
