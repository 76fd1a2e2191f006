"""The option tables of src/option_table.hpp as the Python module sees them: the names written
here by hand (a dropped entry fails), and every function taking an option accepts exactly a
table's names and refuses anything else, naming them."""

import numpy as np
import pytest

import scantrace
from scantrace import _scantrace

NAMES = {
    "shading": ["flat", "gouraud"],
    "fill_rule": ["top-left", "closed"],
    "method": ["exact", "float", "double", "halfspace"],
    "winding_rule": ["even-odd", "non-zero"],
    "cull": ["none", "back", "front"],
    "visibility": ["painter", "zbuffer"],
    "occlusion": ["near-to-far", "far-to-near", "auto"],
    "level": ["triangle", "scanline", "pixel"],
}
DEFAULTS = {"shading": "gouraud", "fill_rule": "top-left", "method": "exact",
            "winding_rule": "even-odd", "cull": "none", "visibility": "painter",
            "occlusion": "auto", "level": "scanline"}

TRI = np.array([[1.0, 1.0], [9.0, 2.0], [4.0, 8.0]])
RGB = np.eye(3)


def test_the_tables_hold_the_names_written_here():
    assert _scantrace.option_names() == NAMES
    assert _scantrace.option_defaults() == DEFAULTS


@pytest.mark.parametrize("key, argument", [("shading", "shading"), ("fill_rule", "fill_rule"),
                                           ("level", "level")])
def test_trace_triangle_takes_exactly_the_names(key, argument):
    for name in _scantrace.option_names()[key]:
        t = scantrace.trace_triangle(TRI, RGB, size=(12, 12), **{argument: name})
        assert getattr(t.header, key) == name
    with pytest.raises(ValueError) as e:
        scantrace.trace_triangle(TRI, RGB, size=(12, 12), **{argument: "bogus"})
    listed = [f"'{n}'" for n in _scantrace.option_names()[key]]
    assert ", ".join(listed[:-1]) + " or " + listed[-1] in str(e.value)


def test_shading_also_takes_first_letters_in_any_case():
    for given, name in [("F", "flat"), ("g", "gouraud"), ("GOURAUD", "gouraud"), ("Flat", "flat")]:
        assert scantrace.trace_triangle(TRI, RGB, size=(12, 12), shading=given).header.shading == name
    with pytest.raises(ValueError, match="expected 'f', 'g', 'flat' or 'gouraud' \\(in any case\\)"):
        scantrace.trace_triangle(TRI, RGB, size=(12, 12), shading="x")
