"""The course's signatures, and the submissions that follow another year's API: read from the AST
(nothing of the student's runs here), mapped parameter by parameter onto the course's arguments
where the mapping is unambiguous. The call then goes through a small adapter inside the sandbox's
harness (harness._adapted), described by the JSON-able dict built here.

The 2024 course: vector_interp(p1, p2, V1, V2, coord, dim), f_shading(img, vertices, vcolors),
g_shading(img, vertices, vcolors), render_img(faces, vertices, vcolors, depth, shading) with
shading 'f' / 'g'. Earlier years asked for interpolate_vectors(p1, p2, V1, V2, xy, dim),
shade_triangle(img, verts2d, vcolors, shade_t) with shade_t the shadings' long names (flat,
Gouraud: the names of the C++ option table, SHADING_NAMES), and
render(verts2d, faces, vcolors, depth, shade_t); students also add a canvas parameter to
render_img, or name the flat fill `flats`.
"""

import ast

from .._common import NAMES

COURSE = {
    "vector_interp": ("p1", "p2", "V1", "V2", "coord", "dim"),
    "f_shading": ("img", "vertices", "vcolors"),
    "g_shading": ("img", "vertices", "vcolors"),
    "render_img": ("faces", "vertices", "vcolors", "depth", "shading"),
}
# Other years' names for each function, in order of preference (a function of its own before
# shade_triangle, which does both fills).
ALIASES = {
    "vector_interp": ("interpolate_vectors", "interpolate_vector"),
    "f_shading": ("flats", "flat_shading", "shade_triangle"),
    "g_shading": ("gourauds", "gouraud_shading", "shade_triangle"),
    "render_img": ("render", "render_image"),
}
# The parameter names students give each role (compared in lower case). Only the roles of the
# function at hand are matched, so `c` (a colour) and `d` (a depth) never meet coord and dim.
ROLE_NAMES = {
    "img": {"img", "image", "canvas", "im", "picture", "x"},
    "vertices": {"vertices", "verts", "verts2d", "vertices2d", "vertex", "points", "pts", "v",
                 "vs", "tri", "triangle", "vertsp", "verts_2d"},
    "vcolors": {"vcolors", "vcolours", "colors", "colours", "vcolor", "vcolour", "color",
                "colour", "c", "cols", "vertex_colors", "vertsc", "rgb"},
    "faces": {"faces", "face", "f", "triangles", "tris", "indices"},
    "depth": {"depth", "depths", "z", "d", "vdepth"},
    "shading": {"shading", "shade_t", "shade", "shading_type", "shade_type", "mode", "method",
                "shader", "s", "type", "kind"},
    "p1": {"p1", "point1", "p_1", "x1"},
    "p2": {"p2", "point2", "p_2", "x2"},
    "V1": {"v1", "c1", "value1", "val1", "v_1"},
    "V2": {"v2", "c2", "value2", "val2", "v_2"},
    "coord": {"coord", "xy", "x", "c", "coordinate", "value", "pos", "p"},
    "dim": {"dim", "dimension", "axis", "d"},
}
CANVAS = [512, 512, 3]
# The shadings' names by the course's letter ('f', 'g'), the first of each name: the names are the
# C++ option table's (src/option_table.hpp), which the package's shading argument also takes.
SHADING_NAMES = {name[0]: name for name in NAMES["shading"]}


def compared_strings(tree):
    """The string constants a module compares with (`shading == 'f'`, `in ('f', 'F')`) or looks
    up by (dict keys: `{'f': f_shading, 'g': g_shading}[shading]`), in lower case: which shading
    values the submission expects."""
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Compare):
            operands = [node.left, *node.comparators]
        elif isinstance(node, ast.Dict):
            operands = [k for k in node.keys if k is not None]    # None: a `**other` entry
        else:
            continue
        for operand in operands:
            items = operand.elts if isinstance(operand, (ast.Tuple, ast.List, ast.Set)) \
                else [operand]
            found |= {e.value.lower() for e in items
                      if isinstance(e, ast.Constant) and isinstance(e.value, str)}
    return found


def shading_values(strings):
    """SHADING_NAMES (each course letter's long name) when the submission compares with the long
    names and never with the course's letters; else None (the course's values)."""
    if set(SHADING_NAMES.values()) & strings and not set(SHADING_NAMES) & strings:
        return dict(SHADING_NAMES)
    return None


def _params(node):
    """(names of the positional parameters, how many have no default)."""
    args = node.args.posonlyargs + node.args.args
    names = [a.arg for a in args]
    if names and names[0] in ("self", "cls"):
        names = names[1:]
    return names, len(names) - len(node.args.defaults)


def _role(name, roles):
    matches = [r for r in roles if name == r or name.lower() in ROLE_NAMES[r]]
    return matches[0] if len(matches) == 1 else None


def _text(name, node):
    return f"{name}({', '.join(_params(node)[0])})"


def adapter(course_name, def_name, node, shading):
    """How to call the student's `def_name` (its FunctionDef `node`) for the course's
    `course_name`: (adapter, note). adapter is None for the course's own signature (called as
    is) and for a signature no mapping fits (called as is: its failures show why); the note is
    "" for the course's signature, else one line for the report."""
    course = COURSE[course_name]
    names, required = _params(node)
    extra = () if course_name == "vector_interp" else \
        tuple(r for r in ("img", "shading") if r not in course)
    roles = [_role(n, course + extra) for n in names]
    fixed = {"shading": course_name[0]} if "shading" in extra and "shading" in roles else {}
    values = shading if ("shading" in course or fixed) else None
    if (def_name == course_name and not values and len(names) == len(course)
            and all(r in (None, c) for r, c in zip(roles, course))):
        return None, ""
    # Trailing parameters with defaults that no course argument needs keep their defaults.
    needed, keep = set(course) | set(fixed), len(roles)
    while keep > required and roles[keep - 1] not in needed:
        keep -= 1
    params = roles[:keep]
    if def_name == course_name and not values and params == list(course):
        return None, ""       # the course's call, an optional parameter left at its default
    what = _text(def_name, node)
    if (None in params or len(set(params)) < len(params) or not set(course) <= set(params)
            or not set(params) <= set(course) | set(extra)):
        return None, (f"`{what}` does not follow the course's `{course_name}"
                      f"({', '.join(course)})`: called as the course's, no adapter fits")
    how = f"`{what}`" + (f" for `{course_name}`" if def_name != course_name else "")
    if "img" in params and "img" not in course:
        how += " (given a blank canvas)"
    if fixed:
        how += f" with {names[roles.index('shading')]} = "
        how += f"'{(values or {}).get(fixed['shading'], fixed['shading'])}'"
    elif values:
        how += " with shading " + " / ".join(f"'{v}'" for v in values.values())
    return {"course": list(course), "params": params, "fixed": fixed, "shading": values or {},
            "canvas": CANVAS}, how
