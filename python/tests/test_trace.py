"""Trace queries, checked against values computed here from the triangle's geometry."""

import math

import numpy as np
import pytest

import scantrace
from conftest import random_scene, run_cli

TRI = np.array([[20.0, 20.0], [250.0, 80.0], [300.0, 400.0]])
RGB = np.eye(3)


def edge_x(p, q, y):
    return p[0] + (y - p[1]) * (q[0] - p[0]) / (q[1] - p[1])


def test_edge_table_of_the_course_triangle():
    t = scantrace.trace_triangle(TRI, RGB)
    table = t.edge_table(0)
    # Edges sorted by first row: e0 (v0 -> v1) and e2 (v2 -> v0) start at y = 20, e1 at y = 80.
    assert [e.edge for e in table.edges] == [0, 2, 1]
    assert table.edges[0].dx_dy == pytest.approx(230 / 60)
    assert table.edges[1].dx_dy == pytest.approx(280 / 380)
    assert table.edges[2].dx_dy == pytest.approx(50 / 320)
    assert (table.edges[2].y_min, table.edges[2].y_max) == (80.0, 400.0)
    assert table.edges[2].x_at_y_min == 250.0
    assert table.horizontal == []


@pytest.mark.parametrize("y", [21, 42, 79, 80, 81, 250, 398])
def test_scanline_points_span_and_colours(y):
    t = scantrace.trace_triangle(TRI, RGB)
    row = t.scanline(0, y)
    v0, v1, v2 = TRI
    left = edge_x(v2, v0, y)
    right = edge_x(v0, v1, y) if y < 80 else edge_x(v1, v2, y)
    xs = [p.x for p in row.active_points]
    assert xs == pytest.approx([left, right], abs=1e-9)
    assert [p.edge for p in row.active_points] == [2, 0 if y < 80 else 1]
    assert row.span.x_begin == math.ceil(left) and row.span.x_end == math.ceil(right)
    # The left point's colour, interpolated along e2 from v0 (red) to v2 (blue).
    s = (y - 20) / 380
    assert row.active_points[0].color == pytest.approx((1 - s, 0, s), abs=1e-9)
    # The image of the traced fill holds the span, and only it, on this row.
    written = np.nonzero((t.image[y] != 1).any(axis=1))[0]
    assert written[0] == row.span.x_begin and written[-1] == row.span.x_end - 1
    assert t.image[y, row.span.x_begin] == pytest.approx(row.span_colors.begin, abs=1e-6)


def test_entered_and_retired():
    t = scantrace.trace_triangle(TRI, RGB)
    # Row 20 only touches the top vertex: both points at x = 20, no pixel centre in between.
    assert [p.x for p in t.scanline(0, 20).active_points] == [20.0, 20.0]
    assert t.scanline(0, 20).span is None
    # Row 399: x from 299.26 to 299.84, no pixel centre in between either.
    assert t.scanline(0, 399).span is None
    assert sorted(t.scanline(0, 20).entered) == [0, 2]
    assert t.scanline(0, 80).entered == [1] and t.scanline(0, 80).retired == [0]
    assert len(t.scanlines(0)) == 380 and t.triangle_end(0).rows == 380


def test_pixel_level_matches_the_image():
    t = scantrace.trace_triangle(TRI, RGB, level="pixel", shading="flat")
    pixels = t.pixels(0)
    written = (t.image != 1).any(axis=2)
    assert len(pixels) == written.sum() == t.triangle_end(0).pixels
    assert all(written[p.y, p.x] for p in pixels[::97])
    assert pixels[0].color == pytest.approx((1 / 3, 1 / 3, 1 / 3))
    assert t.header.level == "pixel" and t.header.shading == "flat"
    assert t.header.canvas == (512, 512)


def test_pixel_history_of_a_scene():
    v, f, c, d = random_scene(5)
    t = scantrace.trace_scene(v, f, c, d)  # scanline level: histories come from the spans
    img = scantrace.render(v, f, c, d)
    assert np.array_equal(t.image, img)
    # Painter's order computed here: mean depth, farthest first, ties in face order.
    order = sorted(range(len(f)), key=lambda i: -d[f[i]].mean())
    assert [i for i in t.triangles()] == order
    # A pixel written by several faces: the last one in painter's order is the final writer.
    ys, xs = np.nonzero((img != 1).any(axis=2))
    for x, y in list(zip(xs, ys))[::500]:
        h = t.pixel_history(int(x), int(y))
        assert len(h) >= 1
        assert h.final().triangle == h.writes[-1].triangle
        assert h.final().color == pytest.approx(tuple(img[y, x]), abs=1e-6)


def test_filters():
    v, f, c, d = random_scene(6)
    t = scantrace.trace_scene(v, f, c, d, triangles=[3, 17], rows=(100, 120))
    assert sorted(t.triangles()) == [i for i in (3, 17) if i in t.triangles()]
    assert set(t.triangles()) <= {3, 17}
    for i in t.triangles():
        if t.skipped(i) is None:
            assert all(100 <= s.y <= 120 for s in t.scanlines(i))
    assert scantrace.trace_scene(v, f, c, d, triangles="3,17").triangles() == t.triangles()
    capped = scantrace.trace_scene(v, f, c, d, max_events=10)
    assert capped.truncated and len(capped) == 12  # header + 10 events + footer


def test_load_a_trace_written_by_the_command(tmp_path):
    path = tmp_path / "triangle.jsonl"
    run_cli("trace", "--triangle", "20,20 250,80 300,400", "-o", path)
    loaded = scantrace.Trace.load(path)
    here = scantrace.trace_triangle(TRI, RGB)
    assert loaded.complete and loaded.image is None
    for y in (21, 150, 398):
        a, b = loaded.scanline(0, y), here.scanline(0, y)
        assert [p.x for p in a.active_points] == [p.x for p in b.active_points]
        assert (a.span.x_begin, a.span.x_end) == (b.span.x_begin, b.span.x_end)
    assert loaded.edge_table(0).edges[1].dx_dy == here.edge_table(0).edges[1].dx_dy


def test_explain_writes_a_video_and_frames(tmp_path):
    small = [[2, 2], [30, 8], [12, 26]]
    r = scantrace.explain(small, RGB, out=tmp_path / "t.mp4", frame_size=(320, 180))
    assert (tmp_path / "t.mp4").stat().st_size > 1000 and r["frames"] > r["steps"] > 5
    t = scantrace.trace_triangle(small, RGB, size=(40, 30))
    r = scantrace.explain(t, out=tmp_path / "frames/", frame_size=(320, 180))
    assert r["format"] == "png"
    assert len(list((tmp_path / "frames").glob("frame_*.png"))) == r["steps"]
