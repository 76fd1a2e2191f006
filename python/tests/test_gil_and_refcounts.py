"""Renders release the GIL; repeated calls leak neither references nor memory."""

import gc
import sys
import threading
import time

import numpy as np

import scantrace


def big_scene():
    # 400 triangles each covering most of a 1024 x 1024 canvas: one call takes well over 50 ms.
    rng = np.random.default_rng(3)
    n = 400
    vertices = np.tile([[-100.0, -100.0], [1300.0, 0.0], [0.0, 1300.0]], (n, 1))
    vertices += rng.uniform(-20, 20, vertices.shape)
    faces = np.arange(3 * n).reshape(n, 3)
    return vertices, faces, rng.uniform(0, 1, (3 * n, 3)), rng.uniform(0, 1, 3 * n)


def python_ticks_during(call):
    """How many times the main thread ran Python code while `call` ran in another thread."""
    started, done = threading.Event(), threading.Event()
    elapsed = []

    def worker():
        started.set()
        t0 = time.perf_counter()
        call()
        elapsed.append(time.perf_counter() - t0)
        done.set()

    thread = threading.Thread(target=worker)
    thread.start()
    started.wait()
    ticks = 0
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    thread.join()
    return ticks, elapsed[0]


def gil_holding_call(seconds):
    """A deliberately wrong call for comparison: C code that keeps the GIL (time.sleep does not,
    so this busy-waits inside one Python-level C call: sum over a big generator-free range).
    Sized on this machine, at this moment: a fixed count took 45 ms on a fast one, too short for
    the comparison to mean anything."""
    n = 1 << 20
    while True:
        start = time.perf_counter()
        sum(range(n))
        if time.perf_counter() - start >= seconds:
            return lambda: sum(range(n))
        n *= 2


def test_render_releases_the_gil():
    scene = big_scene()
    # Eight renders, so that the window is long enough to mean something on a fast, quiet machine
    # too (one render took 45 ms there); each render releases the GIL for all of its work.
    ticks, seconds = python_ticks_during(lambda: [
        scantrace.render(*scene, size=(1024, 1024), shading="gouraud") for _ in range(8)])
    assert seconds > 0.05, "the render must take long enough for the test to mean something"
    # With the GIL released the main thread wakes every millisecond or so during the render.
    assert ticks >= seconds * 1000 / 4, (ticks, seconds)


def test_the_check_tells_a_gil_holder_apart():
    ticks, seconds = python_ticks_during(gil_holding_call(0.3))
    assert seconds > 0.05
    # sum() over a range is one C call that never releases the GIL: the ticker barely runs.
    assert ticks < seconds * 1000 / 4, (ticks, seconds)


def test_g_shading_releases_the_gil():
    img = np.ones((3000, 3000, 3))
    big = [[-10, -10], [6000, 0], [0, 6000]]
    ticks, seconds = python_ticks_during(
        lambda: [scantrace.g_shading(img, big, np.eye(3)) for _ in range(3)])
    assert ticks >= seconds * 1000 / 8, (ticks, seconds)


def rss_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096


def test_no_reference_or_memory_leak_over_10000_calls():
    v = np.array([[1.0, 1.0], [14.0, 3.0], [5.0, 13.0]])
    c = np.eye(3)
    f = np.array([[0, 1, 2]])
    d = np.zeros(3)
    img = np.ones((16, 16, 3))
    args = (v, c, f, d, img)

    def calls():
        scantrace.g_shading(img, v, c)
        r = scantrace.render(v, f, c, d, size=(16, 16))
        assert sys.getrefcount(r) == 2  # the local name and getrefcount's argument
        scantrace.render_img(f, v, c, d, "f")
        t = scantrace.trace_triangle(v, c, size=(16, 16))
        t.scanline(0, 5).active_points[0].x
        t.pixel_history(5, 5).final().color
        scantrace.vector_interp(v[0], v[1], c[0], c[1], 3.0, 1)
        try:
            scantrace.render(v, np.array([[0, 1, 7]]), c, d)
        except ValueError:
            pass

    for _ in range(200):  # warm up: caches, allocator pools
        calls()
    gc.collect()
    before = [sys.getrefcount(a) for a in args]
    rss0 = rss_bytes()
    for _ in range(10_000):
        calls()
    gc.collect()
    assert [sys.getrefcount(a) for a in args] == before
    # Each iteration allocates over 6 MB (render_img's 512 x 512 x 3 doubles) and frees it; a
    # leak of 400 bytes per iteration (one small object per call) would show as 4 MB here.
    assert rss_bytes() - rss0 < 4 * 2**20
