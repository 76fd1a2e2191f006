#!/usr/bin/env python3
"""Validates JSON documents against a JSON Schema (2020-12), e.g. `scantrace why --json` output
against trace/why_schema.json.

    validate_json.py SCHEMA DOCUMENT.json...

Exits 1 on the first invalid document, naming the file and the problem.
"""
import json
import sys

try:
    import jsonschema
except ImportError:
    sys.exit("validate_json: the Python package jsonschema is missing "
             "(Debian: python3-jsonschema; scripts/deps.sh installs it)")


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: validate_json.py SCHEMA DOCUMENT.json...")
    with open(sys.argv[1], encoding="utf-8") as f:
        schema = json.load(f)
    validator = jsonschema.Draft202012Validator(schema)
    for path in sys.argv[2:]:
        with open(path, encoding="utf-8") as f:
            try:
                document = json.load(f)
            except json.JSONDecodeError as e:
                sys.exit(f"{path}: not JSON: {e}")
        errors = sorted(validator.iter_errors(document), key=lambda e: list(e.path))
        if errors:
            sys.exit(f"{path}: {errors[0].message} (at {list(errors[0].absolute_path)})")
    print(f"{len(sys.argv) - 2} documents valid")


main()
