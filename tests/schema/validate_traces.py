#!/usr/bin/env python3
"""Validates scantrace traces (JSON Lines) against trace/trace_schema.json (JSON Schema 2020-12).

    validate_traces.py SCHEMA TRACE.jsonl...

Every line must validate; the first must be the header and the last the footer (the traces the
project writes are complete), and the footer's event count must match the lines between them.
Exits 1 on the first invalid trace, naming the file, the line and the problem.
"""
import json
import sys

try:
    import jsonschema
except ImportError:
    sys.exit("validate_traces: the Python package jsonschema is missing "
             "(Debian: python3-jsonschema; scripts/deps.sh installs it)")


def validate(validator, path):
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    else:
        return f"{path}: the last line does not end with a newline"
    if not lines:
        return f"{path}: empty trace"
    events = []
    for number, line in enumerate(lines, start=1):
        try:
            event = json.loads(line)
        except json.JSONDecodeError as e:
            return f"{path}:{number}: not JSON: {e}"
        errors = sorted(validator.iter_errors(event), key=lambda e: list(e.path))
        if errors:
            return f"{path}:{number}: {errors[0].message} (at {list(errors[0].absolute_path)})"
        events.append(event)
    if events[0]["type"] != "header":
        return f"{path}:1: the first event is {events[0]['type']}, not the header"
    if events[-1]["type"] != "footer":
        return f"{path}:{len(events)}: the last event is {events[-1]['type']}, not the footer"
    types = [e["type"] for e in events]
    if types.count("header") != 1 or types.count("footer") != 1:
        return f"{path}: exactly one header and one footer expected"
    if events[-1]["events"] != len(events) - 2:
        return f"{path}: footer counts {events[-1]['events']} events, the file has {len(events) - 2}"
    return None


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    with open(sys.argv[1], encoding="utf-8") as f:
        schema = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    passed = failed = 0
    for path in sys.argv[2:]:
        problem = validate(validator, path)
        if problem:
            print(problem, file=sys.stderr)
            failed += 1
        else:
            passed += 1
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
