"""Helpers that the public functions (_api.py) and the grading layer (_grade.py) both need: kept
here so that neither module imports the other (tests/test_import_graph.py holds the package free
of import cycles)."""

import os

from . import _scantrace

# The fill options' defaults, from the C++ option tables (src/option_table.hpp): the names the
# command line, the trace header and the JavaScript API also read there, spelled in one place.
DEFAULT = _scantrace.option_defaults()
SHADING, FILL_RULE = DEFAULT["shading"], DEFAULT["fill_rule"]
# Each option's names by key, in the tables' order (the shadings: flat, then Gouraud).
NAMES = _scantrace.option_names()


def load_scene_file(path, shading):
    """A scene file as load_scene() returns it (_api.load_scene documents the formats)."""
    return _scantrace.load_scene(os.fspath(path), shading)


def cv_module(what):
    """The package's OpenCV part, or an error saying what needs it and how to get it."""
    try:
        from . import _scantrace_cv   # optional: only builds with SCANTRACE_PYTHON_OPENCV have it
    except ImportError as e:
        raise ModuleNotFoundError(
            f"{what} needs scantrace's OpenCV module (scantrace._scantrace_cv), which this "
            "installation does not have: `pip install` leaves it out unless "
            "SCANTRACE_PYTHON_OPENCV=1 is set (it links OpenCV, Debian's libopencv-dev). "
            "Arrays and .npy files need no OpenCV.") from e
    return _scantrace_cv
