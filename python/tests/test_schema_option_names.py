"""The JSON Schemas of the trace and why formats (trace/trace_schema.json, trace/why_schema.json)
list each option's names as an enum: they are the C++ option tables' (src/option_table.hpp), the
tables the writers take the names from, read here through _scantrace.option_names(). A name added
to, renamed in or dropped from a table fails here until the schema says the same."""

import json

import pytest

from scantrace import _scantrace

from conftest import SOURCE_DIR

# Each schema, with the options its documents must carry an enum of (so a schema that lost one,
# or a walk that finds none, fails rather than passing on nothing).
SCHEMAS = {
    "trace/trace_schema.json": {"shading", "fill_rule", "level", "winding_rule", "visibility",
                                "cull"},
    "trace/why_schema.json": {"shading", "fill_rule", "visibility"},
}


def option_enums(node, names, found):
    """Every `properties` entry of the schema named like an option table that has an enum:
    {key: [its enum, ...]}, one list per place it appears."""
    if isinstance(node, dict):
        for key, sub in node.get("properties", {}).items():
            if key in names and isinstance(sub, dict) and "enum" in sub:
                found.setdefault(key, []).append(sub["enum"])
        for sub in node.values():
            option_enums(sub, names, found)
    elif isinstance(node, list):
        for sub in node:
            option_enums(sub, names, found)
    return found


@pytest.mark.parametrize("schema", sorted(SCHEMAS))
def test_schema_enums_are_the_option_tables_names(schema):
    names = _scantrace.option_names()
    found = option_enums(json.loads((SOURCE_DIR / schema).read_text()), names, {})
    assert SCHEMAS[schema] <= set(found), f"{schema} has no enum for {SCHEMAS[schema] - set(found)}"
    for key, enums in found.items():
        for enum in enums:
            assert enum == names[key], f"{schema}: {key} lists {enum}, the table {names[key]}"
