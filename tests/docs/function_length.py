#!/usr/bin/env python3
"""No function of the production code is longer than 80 lines (docs/architecture.md, "Style").

A function that grows past 80 lines is asking to be split into named steps. The production code
is every C++, JavaScript and Python file the repository holds outside tests/, examples/, fuzz/ and
the benchmarks' own programs; a file is read as the repository holds it (`git ls-files`), so what
a build leaves beside the sources does not count.

C++ and JavaScript functions are found by their opening line (a signature ending in `) {`, an
arrow `=> {` or `function … {`) and measured to the matching brace, with comments and string
literals left out of the brace count; Python functions by the ast. A body counted inside a longer
one (a lambda, a nested function) is part of that function's lines.

ALLOWED names the functions that may be longer, each with its reason (at most two).

usage: function_length.py SOURCE_DIR [--limit N]
"""
import ast
import re
import subprocess
import sys
from pathlib import Path

LIMIT = 80
ALLOWED = {}  # "path:function opening line text": "the reason it stays one function"
PRODUCTION = ("src/", "trace/", "io/", "viz/", "grade/", "cli/", "web/", "python/scantrace/",
              "python/src/", "reference/", "demo/", "stress/")
EXCLUDED_PARTS = ("/tests/", "/test/", "/bench/", "/node_modules/")

SIGNATURE = re.compile(r"\)\s*(const)?\s*(noexcept)?\s*(override)?\s*(->\s*[\w:<>,\s]+)?\s*\{$")
ARROW = re.compile(r"=>\s*\{$")
JS_FUNCTION = re.compile(r"\bfunction\b[\s\w$]*\([^)]*\)\s*\{$")
CONTROL = re.compile(r"^\s*(\}\s*)?(if|for|while|switch|else|do|catch|try|return|case)\b")
STRING_OR_COMMENT = re.compile(
    r'//[^\n]*|/\*.*?\*/|R"(\w*)\(.*?\)\1"|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|`(?:\\.|[^`\\])*`',
    re.S)


def blank_out(text):
    """The text with comments and literals replaced by spaces, newlines kept (line numbers hold)."""
    return STRING_OR_COMMENT.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def opens_function(line, javascript):
    code = line.rstrip()
    if not code.endswith("{") or CONTROL.match(code):
        return False
    if javascript and (ARROW.search(code) or JS_FUNCTION.search(code)):
        return True
    if not SIGNATURE.search(code):
        return False
    head = code.split("(")[0]
    # `x = f(…) {` is not a definition in C++; in JavaScript a method `name(…) {` is.
    return "=" not in head and not code.lstrip().startswith(("[", "&", ".", ")"))


def brace_functions(text, javascript):
    """(first line, length, opening text) of each outermost function body."""
    lines = blank_out(text).split("\n")
    raw = text.split("\n")
    found, i = [], 0
    while i < len(lines):
        if not opens_function(lines[i], javascript):
            i += 1
            continue
        depth, j = 0, i
        while j < len(lines):
            depth += lines[j].count("{") - lines[j].count("}")
            if depth <= 0:
                break
            j += 1
        found.append((i + 1, j - i + 1, raw[i].strip()))
        i = j + 1
    return found


def python_functions(text):
    found = []
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            found.append((node.lineno, node.end_lineno - node.lineno + 1, "def " + node.name))
    return found


def production_files(source):
    listed = subprocess.run(["git", "-C", str(source), "ls-files", "-z"], capture_output=True,
                            text=True, check=True).stdout.split("\0")
    for path in listed:
        if path.startswith(PRODUCTION) and not any(p in "/" + path for p in EXCLUDED_PARTS) \
                and path.endswith((".cpp", ".hpp", ".h", ".js", ".mjs", ".py")):
            yield path


def long_functions(source, limit):
    for path in production_files(source):
        text = (Path(source) / path).read_text(encoding="utf-8", errors="replace")
        if path.endswith(".py"):
            functions = python_functions(text)
        else:
            functions = brace_functions(text, path.endswith((".js", ".mjs")))
        for line, length, opening in functions:
            if length > limit:
                yield path, line, length, opening


def main():
    source = Path(sys.argv[1])
    limit = int(sys.argv[sys.argv.index("--limit") + 1]) if "--limit" in sys.argv else LIMIT
    if len(ALLOWED) > 2:
        sys.exit("function_length.py: at most two functions may be allowed to be long")
    failures = []
    for path, line, length, opening in long_functions(source, limit):
        if f"{path}:{opening}" in ALLOWED:
            print(f"allowed: {path}:{line} {length} lines ({ALLOWED[f'{path}:{opening}']})")
            continue
        failures.append(f"{path}:{line}: {length} lines, over {limit}: {opening}")
    if failures:
        print("\n".join(failures))
        sys.exit(f"{len(failures)} function(s) over {limit} lines: split them into named steps")
    print(f"no production function over {limit} lines")


if __name__ == "__main__":
    main()
