"""What the objects say about themselves: repr() of the trace's objects, and the Jupyter outputs
(Image's PNG, DiffReport's HTML, PixelStory's Markdown), each within its size bound."""

import base64
import re
import struct
import zlib

import numpy as np
import pytest

import scantrace
from scantrace import _jupyter

TRIANGLE = [[20, 20], [250, 80], [300, 400]]


@pytest.fixture(scope="module")
def trace():
    return scantrace.trace_triangle(TRIANGLE, np.eye(3))


def test_trace_repr_says_what_it_holds(trace):
    r = repr(trace)
    assert r.startswith("<Trace: 1 triangle [0], ")
    assert f"{len(trace)} events" in r and "level 'scanline'" in r
    assert "512x512 gouraud top-left" in r and "with its image" in r
    assert "object at 0x" not in r


def test_header_edge_table_scanline_reprs(trace):
    h = repr(trace.header)
    assert h.startswith("Header(canvas=(512, 512), shading='gouraud', fill_rule='top-left', "
                        "level='scanline'")
    et = trace.edge_table(0)
    r = repr(et)
    assert r.startswith("EdgeTable(triangle=0, edges=[EdgeEntry(edge=")
    assert r.count("EdgeEntry(") == len(et.edges) == 3
    row = trace.scanline(0, 42)
    r = repr(row)
    assert r.startswith("Scanline(triangle=0, y=42, span=Span(x_begin=")
    assert f"x_begin={row.span.x_begin}, x_end={row.span.x_end}" in r
    assert r.count("ActivePoint(") == 2 and "span_colors=SpanColors(begin=" in r


def test_pixel_history_repr_and_final(trace):
    inside = trace.pixel_history(200, 150)
    assert len(inside) == 1 and inside.final().triangle == 0
    assert repr(inside).startswith("PixelHistory(1 write, final=PixelWrite(triangle=0, color=(")
    # The README's example: a pixel no triangle wrote is an empty history, final() None.
    outside = trace.pixel_history(100, 200)
    assert outside.empty() and len(outside) == 0 and outside.final() is None
    assert repr(outside) == "PixelHistory(empty: no triangle wrote this pixel)"


def png_size(data):
    """Width and height from a PNG's IHDR, checking the signature and that every chunk's CRC is
    right (a decoder's first checks, written here from the format)."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    at, chunks = 8, []
    while at < len(data):
        (n,) = struct.unpack(">I", data[at:at + 4])
        kind, body = data[at + 4:at + 8], data[at + 8:at + 8 + n]
        assert struct.unpack(">I", data[at + 8 + n:at + 12 + n])[0] == zlib.crc32(kind + body)
        chunks.append((kind, body))
        at += 12 + n
    assert chunks[0][0] == b"IHDR" and chunks[-1][0] == b"IEND"
    return struct.unpack(">II", chunks[0][1][:8])


def test_image_shows_itself_as_a_png():
    img = scantrace.render_img([[0, 1, 2]], [[1, 1], [40, 2], [3, 30]], np.eye(3), np.zeros(3), "g")
    shown = scantrace.Image(img)
    assert repr(shown) == "<Image 512x512 float64>"
    assert png_size(shown._repr_png_()) == (512, 512)


def test_a_large_image_is_shown_subsampled_within_the_bound():
    rng = np.random.default_rng(1)
    noise = rng.integers(0, 256, (3000, 2000, 3), dtype=np.uint8)
    data = scantrace.Image(noise)._repr_png_()
    w, h = png_size(data)
    # 6 Mpx: every third row and column (step 2 would leave 1.5 Mpx).
    assert (w, h) == (667, 1000) and w * h <= _jupyter.MAX_SHOWN_PIXELS
    # Noise does not compress: the bound on pixels is what bounds the bytes.
    assert len(data) <= 3 * _jupyter.MAX_SHOWN_PIXELS + 100_000


def test_image_refuses_what_is_not_an_image():
    with pytest.raises(ValueError, match=r"expected an image of shape \(H, W, 3\), got \(4, 4\)"):
        scantrace.Image(np.zeros((4, 4)))
    with pytest.raises(TypeError, match="expected a float or uint8 image, got dtype int64"):
        scantrace.Image(np.zeros((4, 4, 3), np.int64))


@pytest.fixture(scope="module")
def course_like():
    rng = np.random.default_rng(5)
    v = rng.uniform(0, 512, (300, 2))
    f = rng.integers(0, 300, (400, 3))
    c = rng.uniform(0, 1, (300, 3))
    z = rng.uniform(0, 10, 300)
    return f, v, c, z


def test_diff_report_html_has_the_table_and_the_picture(course_like):
    f, v, c, z = course_like
    img = scantrace.render(v, f, c, z)
    img[200:240, 200:260] = 0.5
    report = scantrace.diff(course_like, img)
    out = report._repr_html_()
    assert f"<b>{report.differing_pixels} of 262144 pixels differ" in out
    for name, count in report.categories.items():
        assert re.search(rf"{name}</td><td[^>]*>{count}</td>", out), name
    data = base64.b64decode(re.search(r'data:image/png;base64,([A-Za-z0-9+/=]+)"', out).group(1))
    assert png_size(data) == (512, 512)
    assert len(out) < 1_000_000


def test_diff_report_html_of_an_agreeing_image(course_like):
    f, v, c, z = course_like
    out = scantrace.diff(course_like, scantrace.render(v, f, c, z))._repr_html_()
    assert "<b>The image agrees with the reference</b>" in out


def test_pixel_story_markdown_lists_the_faces(course_like):
    story = scantrace.why(course_like, 256, 256)
    md = story._repr_markdown_()
    assert md.startswith("**Pixel (256, 256)** of the 512x512 canvas")
    rows = [line for line in md.splitlines() if re.match(r"\| \d+ \|", line)]
    assert len(rows) == min(len(story.faces), _jupyter.MAX_STORY_FACES)
    for face, row in zip(story.faces, rows):
        assert row.startswith(f"| {face['face']} |") and f"`{face['outcome']}`" in row


def test_pixel_story_markdown_is_bounded():
    # 200 faces over one pixel: the table stops at the bound and says how many it left out.
    n = 200
    v = np.array([[0, 0], [100, 0], [0, 100]] * n, float)
    f = np.arange(3 * n).reshape(n, 3)
    c = np.tile(np.eye(3), (n, 1))
    z = np.arange(3 * n, dtype=float)
    md = scantrace.why((f, v, c, z), 10, 10)._repr_markdown_()
    assert f"… {n - _jupyter.MAX_STORY_FACES} more faces" in md
    assert len(md) < 20_000
