"""scantrace from Python: the exact edge-table scanline fill of the course, numpy in and out.

The course's functions, with the course's signatures and conventions:

    vector_interp(p1, p2, V1, V2, coord, dim)
    f_shading(img, vertices, vcolors)        # img: M x N x 3 floats in [0, 1], filled in place
    g_shading(img, vertices, vcolors)
    render_img(faces, vertices, vcolors, depth, shading)   # 512 x 512 x 3 on white

and beyond them: render(), load_scene(), demo_scene(), write_png(), trace_triangle(), trace_scene(),
Trace.load() and explain(); and the grading questions, on the same C++ code as the command line:

    why(scene, x, y)        # PixelStory: why pixel (x, y) has its colour (scantrace why)
    diff(scene, image)      # DiffReport: where and why an image differs (scantrace diff)
    check(trace)            # CheckResult: does a trace agree with exact arithmetic (scantrace check)
    Image(render_img(...))  # shows itself in Jupyter as a PNG
    trace.frame(10).to_svg()  # a replay frame (the display list) as SVG, or to_json()
    trace                   # in Jupyter: an inline player stepping through the replay

A scene is a path, the dict load_scene() returns, or (faces, vertices, vcolors, depth). Coordinates are [x, y] with x the column and y the row (pointing
down); pixel (x, y) is centred on the integer point (x, y) and is img[y, x]. The fill rule is
top-left (half-open) unless fill_rule='closed'.

Every function is the C++ library's own fill (the same code as the `scantrace` command), so a
render here equals the command's render value for value. Renders release the GIL.
"""

from ._api import (
    InputError,
    Trace,
    demo_scene,
    explain,
    f_shading,
    g_shading,
    load_scene,
    render,
    render_img,
    trace_scene,
    trace_triangle,
    vector_interp,
    write_png,
)
from ._grade import CheckResult, DiffReport, PixelStory, check, diff, why
from ._jupyter import Image
from ._player import Player
from ._scantrace import Frame, Frames
from ._scantrace import __version__

__all__ = [
    "CheckResult",
    "DiffReport",
    "Frame",
    "Frames",
    "Image",
    "InputError",
    "Player",
    "PixelStory",
    "Trace",
    "check",
    "demo_scene",
    "diff",
    "explain",
    "f_shading",
    "g_shading",
    "load_scene",
    "render",
    "render_img",
    "trace_scene",
    "trace_triangle",
    "vector_interp",
    "why",
    "write_png",
    "__version__",
]
