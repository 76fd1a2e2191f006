#!/usr/bin/env python3
"""The trace schema rejects what is not trace format v1: each event below is a valid event with one
mistake (a misspelt key, an unknown key, a missing or mistyped field), and must fail validation,
while the same event without the mistake must pass (so a schema that accepts everything fails).

    invalid_traces_rejected.py SCHEMA
"""
import copy
import json
import sys

import jsonschema

HEADER = {"type": "header", "format": "scantrace-trace", "version": 1,
          "canvas": {"width": 16, "height": 12}, "shading": "gouraud", "fill_rule": "top-left",
          "subpixel_bits": 8, "level": "scanline", "generator": "scantrace 0.1.0"}
BEGIN = {"type": "triangle_begin", "triangle": 0, "vertices": [[1, 1], [9, 2], [4, 8]],
         "snapped": [[1, 1], [9, 2], [4, 8]], "colors": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
         "vertex_depths": [0.5, 0.25, 1]}
SCANLINE = {"type": "scanline", "triangle": 0, "y": 3, "entered": [], "retired": [],
            "active_edges": [{"edge": 0, "x": 1.5}, {"edge": 1, "x": 8.25}],
            "active_points": [{"x": 1.5, "edge": 0, "color": [1, 0, 0]},
                              {"x": 8.25, "edge": 1, "color": [0, 1, 0]}],
            "span": {"x_begin": 2, "x_end": 9}}
PIXEL = {"type": "pixel", "triangle": 0, "x": 3, "y": 3, "color": [1, 0, 0], "t": 0.25}
FOOTER = {"type": "footer", "events": 3, "truncated": False}


def mutate(event, path, value=None, delete=False):
    e = copy.deepcopy(event)
    target = e
    for key in path[:-1]:
        target = target[key]
    if delete:
        del target[path[-1]]
    else:
        target[path[-1]] = value
    return e


def rename(event, old, new):
    e = copy.deepcopy(event)
    e[new] = e.pop(old)
    return e


VALID = [HEADER, BEGIN, SCANLINE, PIXEL, FOOTER,
         mutate(HEADER, ["visibility"], "zbuffer"), mutate(HEADER, ["background"], [0, 0, 0])]
INVALID = {
    "header: misspelt optional key (visibilty)": mutate(HEADER, ["visibilty"], "zbuffer"),
    "header: misspelt required key (fill-rule)": rename(HEADER, "fill_rule", "fill-rule"),
    "header: unknown key in canvas": mutate(HEADER, ["canvas", "depth"], 3),
    "header: wrong version": mutate(HEADER, ["version"], 2),
    "triangle_begin: misspelt key (vertex_depth)": rename(BEGIN, "vertex_depths", "vertex_depth"),
    "triangle_begin: two vertex depths": mutate(BEGIN, ["vertex_depths"], [0, 1]),
    "scanline: unknown key in an active edge": mutate(SCANLINE, ["active_edges", 0, "slope"], 1),
    "scanline: span without x_end": mutate(SCANLINE, ["span", "x_end"], delete=True),
    "pixel: colour out of range": mutate(PIXEL, ["color"], [2, 0, 0]),
    "pixel: misspelt key (colour)": rename(PIXEL, "color", "colour"),
    "footer: truncated is not a boolean": mutate(FOOTER, ["truncated"], "no"),
    "footer: extra key": mutate(FOOTER, ["complete"], True),
    "unknown event type": {"type": "row", "y": 3},
}


def main():
    with open(sys.argv[1], encoding="utf-8") as f:
        schema = json.load(f)
    validator = jsonschema.Draft202012Validator(schema)
    failures = 0
    for event in VALID:
        errors = list(validator.iter_errors(event))
        if errors:
            print(f"a valid {event['type']} event was rejected: {errors[0].message}", file=sys.stderr)
            failures += 1
    for name, event in INVALID.items():
        if validator.is_valid(event):
            print(f"accepted, but invalid: {name}", file=sys.stderr)
            failures += 1
    print(f"{len(VALID)} valid events, {len(INVALID)} invalid ones; {failures} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
