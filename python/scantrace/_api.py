"""The public functions: defaults, docstrings, and the calls into the C++ core (_scantrace).

Arguments are checked in the core, which names the argument, the expected shape or dtype and
what was given (``vertices: expected an array of shape (3, 2), got (2, 3)``): wrong kinds and
dtypes are TypeError, wrong shapes, NaN, infinity and indices out of range are ValueError.
"""

import os

import numpy as np

from . import _scantrace
from ._common import FILL_RULE, SHADING, cv_module, load_scene_file
from ._scantrace import InputError, Trace

_WHITE = (1.0, 1.0, 1.0)
_COURSE_SIZE = (512, 512)


def vector_interp(p1, p2, V1, V2, coord, dim):
    """Linear interpolation of V1 (at p1) and V2 (at p2), the course's ``vector_interp``.

    p1, p2: points ``[x, y]``. V1, V2: values of the same shape (a colour, a scalar, any
    array). coord: the x (``dim=1``) or y (``dim=2``) coordinate of the point where the value is
    wanted. Returns the value there (a float for scalar V1, V2; else a float64 array of their
    shape); outside the segment the line is extended.

    Degenerate case: when p1 and p2 have the same coordinate along ``dim`` (including p1 == p2)
    the position is undefined and the result is the midpoint value (V1 + V2) / 2, as in the C++
    function (symmetric, so swapping the endpoints never changes a pixel).
    """
    return _scantrace.vector_interp(p1, p2, V1, V2, coord, dim)


def f_shading(img, vertices, vcolors):
    """Fills one triangle with flat shading (the mean of its vertex colours), the course's way.

    img: a float32 or float64 numpy array of shape (M, N, 3), RGB in [0, 1]; it is filled in
    place *and* returned. vertices: 3 x 2, the ``[x, y]`` of each vertex (x = column, y = row).
    vcolors: 3 x 3, the RGB colour of each vertex, in [0, 1].

    Pixels whose centre is inside the triangle, or on its top or left edge, are written (the
    top-left rule: triangles sharing an edge never both write a pixel). The values written are
    those of the C++ float canvas (float32; in a float64 array, widened exactly).
    """
    return _scantrace.f_shading(img, vertices, vcolors)


def g_shading(img, vertices, vcolors):
    """Fills one triangle with Gouraud shading, the course's way.

    The vertex colours are interpolated along the two active edges of each row, then along the
    row (``vector_interp`` twice). Arguments and result as :func:`f_shading`.
    """
    return _scantrace.g_shading(img, vertices, vcolors)


def _course_shading(shading):
    if not isinstance(shading, str):
        raise TypeError(f"shading: expected 'f' or 'g', got {type(shading).__name__}")
    return shading


def render_img(faces, vertices, vcolors, depth, shading):
    """Renders a scene the course's way: a 512 x 512 x 3 float64 image on white.

    faces: K x 3 vertex indices (0-based). vertices: L x 2 ``[x, y]``. vcolors: L x 3 RGB in
    [0, 1]. depth: L (or L x 1), one depth per vertex. shading: ``'f'`` (flat) or ``'g'``
    (Gouraud); the long names, ``flat`` and ``gouraud`` (the C++ option table's), are accepted
    too, in any case (``'F'``, ``'Flat'``). Note the course's order, faces first; :func:`render` takes vertices first (a
    swap is named in the error).

    Painter's order: a face's depth is the mean of its vertex depths; the deepest is drawn
    first, ties keep face order. The result equals the C++ render (``scantrace render``) value
    for value; :func:`write_png` of it gives the same PNG bytes as the command.
    """
    return _scantrace.render(
        vertices, faces, vcolors, depth,
        shading=_course_shading(shading), fill_rule=FILL_RULE, size=_COURSE_SIZE,
        background=_WHITE, dtype=np.float64)


def render(vertices, faces, vcolors, depth, *, shading=SHADING, fill_rule=FILL_RULE,
           size=_COURSE_SIZE, background=_WHITE, dtype=np.float64):
    """Renders a scene in painter's order and returns the image.

    vertices (L x 2), faces (K x 3), vcolors (L x 3), depth (L): as :func:`render_img`.
    shading: the string ``gouraud``/``g`` or ``flat``/``f``. fill_rule: ``top-left`` (each pixel
    of a mesh written once) or ``closed`` (every centre on the boundary too, as the course and
    OpenCV). size: ``(width, height)``; the image has shape ``(height, width, 3)``.
    background: RGB in [0, 1]. dtype: ``np.float64`` (default), ``np.float32`` (the C++ float
    canvas itself) or ``np.uint8`` (``round(255 c)``: the bytes of the command's PNG).

    The scene dict of :func:`load_scene` can be passed as ``render(**scene)``. Arrays of the
    right dtype and layout (float64, int64 faces, C order) are read without a copy.
    """
    return _scantrace.render(vertices, faces, vcolors, depth, shading=shading,
                             fill_rule=fill_rule, size=size, background=background, dtype=dtype)


def load_scene(path, *, shading=SHADING):
    """Reads a scene into a dict of numpy arrays: a scene file (the course's JSON keys), the
    course's own ``hw1.npy`` (a pickled dict of four arrays, read by a restricted reader that
    constructs nothing but those arrays: never Python's unpickler), a MATLAB ``.mat`` scene of
    the 2021 course, or an OBJ model.

    Returns ``{'vertices', 'faces', 'vcolors', 'depth', 'size', 'background'}``, ready for
    ``render(**scene)`` or ``trace_scene(**scene)``; ``render_img`` takes the first four. An OBJ
    model is lit and projected as ``scantrace render model.obj`` does by default (``shading``
    chooses per-face or per-corner lighting). A bad file raises :class:`InputError` (a
    ValueError) naming the file and the element: ``scene.json: faces[812]: vertex index 5012 is
    out of range (4999 vertices)``.
    """
    return load_scene_file(path, shading)


def demo_scene():
    """The built-in scene of ``scantrace demo``, generated (no file needed): a jittered grid mesh
    coloured by a hue wheel, a sun of thin triangles around one vertex and three large
    overlapping triangles at different depths, on a 512 x 512 canvas. The same dict as
    :func:`load_scene`: ``render(**demo_scene())``, ``render_img`` takes its first four arrays.
    """
    return _scantrace.demo_scene()


def write_png(img, path):
    """Writes an M x N x 3 float image (RGB in [0, 1]) as an 8-bit PNG, ``round(255 c)``.

    The conversion and the encoder are those of ``scantrace render``, so a render of the same
    scene gives the same bytes. The file is written under a temporary name and renamed into place.
    """
    _scantrace.write_png(img, os.fspath(path))


def trace_triangle(vertices, vcolors, *, shading=SHADING, fill_rule=FILL_RULE,
                   level="scanline", size=_COURSE_SIZE, background=_WHITE, face=0):
    """Fills one triangle with the real fill and returns its :class:`Trace`, recorded in memory.

    level: ``'triangle'`` (edge table), ``'scanline'`` (adds every row: active edges, active
    points, span, span colours) or ``'pixel'`` (adds every pixel). face: the index the trace
    calls the triangle by, 0 unless given: a face taken out of a scene keeps its number with
    ``trace_triangle(v[f[3109]], c[f[3109]], face=3109)`` (then ``t.scanline(3109, y)``).
    ``t.scanline(i, y)`` for a row the triangle does not fill raises IndexError saying why (its
    rows are ``ceil(y_min) .. ceil(y_max) − 1``: the top-left rule leaves the bottom vertex's row
    out). With face 0::

        t = trace_triangle([[20, 20], [250, 80], [300, 400]], np.eye(3))
        t.edge_table(0).edges[1].dx_dy
        t.scanline(0, 42).active_points[0].x
        t.scanline(0, 42).span.x_begin
        t.pixel_history(200, 200).final().color   # (100, 200) is outside the triangle
        t.image                               # the image the traced fill drew (float64)
    """
    return _scantrace.trace_triangle(vertices, vcolors, shading=shading, fill_rule=fill_rule,
                                     level=level, size=size, background=background, face=face)


def trace_scene(vertices, faces, vcolors, depth, *, shading=SHADING, fill_rule=FILL_RULE,
                level="scanline", triangles=None, rows=None, max_events=None,
                size=_COURSE_SIZE, background=_WHITE):
    """Renders a scene in painter's order with the real fill and returns its :class:`Trace`.

    triangles: the faces to trace (indices, or a string ``"3,17,40-45"``); rows: ``(first,
    last)``, inclusive; max_events: a cap on the events. Untraced faces are still drawn, so
    ``pixel_history`` and ``image`` describe the whole render.
    """
    return _scantrace.trace_scene(vertices, faces, vcolors, depth, shading=shading,
                                  fill_rule=fill_rule, level=level, triangles=triangles,
                                  rows=rows, max_events=max_events, size=size,
                                  background=background)


def explain(trace_or_vertices, vcolors=None, *, out="triangle.mp4", shading=SHADING,
            fill_rule=FILL_RULE, frame_size=(1280, 720), fps=5.0, hold=0.8):
    """Writes the explanatory video of a fill (``scantrace explain``): H.264 MP4, or a directory
    of PNG frames when ``out`` ends with ``/`` or has no extension.

    Pass a :class:`Trace`, or a triangle's vertices (3 x 2) and vcolors (3 x 3). Returns
    ``{'path', 'format', 'steps', 'frames', 'seconds'}``.
    """
    if isinstance(trace_or_vertices, Trace):
        if vcolors is not None:
            raise TypeError("explain: vcolors is given with a Trace; pass one or the other")
        trace, source = trace_or_vertices, "the trace"
    else:
        if vcolors is None:
            raise TypeError("explain: vcolors is missing (3 x 3, one RGB colour per vertex)")
        trace = trace_triangle(trace_or_vertices, vcolors, shading=shading, fill_rule=fill_rule)
        source = "a triangle from Python"
    video = cv_module("explain (writing a video or PNG frames)")
    return video.replay(trace, os.fspath(out), frame_size=frame_size, fps=fps, hold=hold,
                        source=source)
