#!/usr/bin/env python3
"""Every C++ and Python code example of README.md and docs/*.md is compiled or run, and the values
it promises are checked (issue 36: README's `t.pixel_history(100, 200).final()` aborted, the
pixel being outside the course triangle).

A code example is a fenced block labelled ```cpp or ```python. A line of it whose comment starts
with `→ VALUE` (`// → 79: the first pixel …`, `# → 37: …`) promises that the expression before the
comment has that value: VALUE runs to the first ": " or the end of the line. Numbers compare to
the precision they are written with (78.947 is 78.9474 ± 0.0005); the rest of the text exactly.

  generate OUT.cpp SOURCE_DIR
      writes one C++ program holding every ```cpp block as a function (its #include lines at the
      top of the file, its `using` lines in the function's namespace), a checked expression as a
      call of doc_check::check; `main` runs them all (CMake builds it: tests/CMakeLists.txt).
  run SOURCE_DIR SNIPPETS_PROGRAM SCANTRACE_BINARY PYTHON_BUILD_DIR WORK_DIR
      in WORK_DIR, first the README's commands that make the files the examples read
      (`scantrace trace --triangle … -o triangle.jsonl`, the demo's scene as scene.json), then the
      C++ program, then every ```python block line by line (PYTHONPATH=PYTHON_BUILD_DIR).
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

ARROW = "→"


def blocks(source, language):
    """(file:line, [lines]) of every fenced block labelled `language`."""
    found = []
    for f in [source / "README.md"] + sorted((source / "docs").glob("*.md")):
        lines = f.read_text(encoding="utf-8").split("\n")
        current = None
        for n, line in enumerate(lines, 1):
            fence = re.match(r"^```(\w*)", line)
            if fence and current is None:
                if fence.group(1) == language:
                    current = (f"{f.relative_to(source)}:{n + 1}", [])
                    found.append(current)
                else:
                    current = ("other", [])
            elif fence:
                current = None
            elif current is not None:
                current[1].append(line)
    return found


def split_promise(line, comment):
    """(code, promised value or None) of one line; `comment` is "//" or "#"."""
    marker = f"{comment} {ARROW} "
    at = line.find(marker)
    if at < 0:
        return line, None
    value = line[at + len(marker):]
    return line[:at].rstrip(), value.split(": ")[0].strip()


def same_value(got, expected):
    """Numbers within the precision `expected` is written with; everything else exactly."""
    number = r"-?\d+(?:\.\d+)?(?:e-?\d+)?"
    got_parts, expected_parts = re.split(number, got), re.split(number, expected)
    got_numbers, expected_numbers = re.findall(number, got), re.findall(number, expected)
    if [p.strip() for p in got_parts] != [p.strip() for p in expected_parts] or \
            len(got_numbers) != len(expected_numbers):
        return False
    for g, e in zip(got_numbers, expected_numbers):
        decimals = len(e.split(".")[1]) if "." in e and "e" not in e else 0
        if abs(float(g) - float(e)) > 0.5 * 10 ** -decimals + 1e-12:
            return False
    return True


CHECK_CPP = r'''
namespace doc_check {
// The value of a promised expression, as the docs write it, against the promise.
template <class T>
void check(const char* where, const T& value, const char* expected, const char* expression) {
  std::ostringstream text;
  text.precision(10);
  text << value;
  std::cout << where << ": " << expression << " = " << text.str() << " (docs: " << expected
            << ")" << std::endl;
  std::cout << "CHECK\t" << where << "\t" << text.str() << "\t" << expected << std::endl;
}
}  // namespace doc_check
'''


def generate(out, source):
    includes, functions, names = [], [], []
    for i, (where, lines) in enumerate(blocks(source, "cpp")):
        body, usings = [], []
        file, first = where.rsplit(":", 1)
        for k, line in enumerate(lines):
            here = f"{file}:{int(first) + k}"
            if line.startswith("#include"):
                includes.append(line)
                continue
            if line.startswith("using "):
                usings.append(line)
                continue
            code, promise = split_promise(line, "//")
            if promise is not None:
                expression = code.rstrip().rstrip(";")
                literal = expression.replace("\\", "\\\\").replace('"', '\\"')
                body.append(f'  doc_check::check("{here}", {expression}, "{promise}", "{literal}");')
            else:
                body.append(f"#line {int(first) + k} \"{file}\"\n  {line}")
        name = f"block_{i}"
        names.append((name, where))
        functions.append(f"namespace {name} {{\n" + "\n".join(usings) + "\nvoid run() {\n" +
                         "\n".join(body) + "\n}\n}  // namespace " + name + "\n")
    text = ["// Generated by tests/docs/doc_snippets.py from the ```cpp blocks of README.md and",
            "// docs/*.md: edit those, not this.",
            "#include <exception>", "#include <iostream>", "#include <sstream>"]
    text += sorted(set(includes)) + [CHECK_CPP] + functions
    text.append("int main() {\n  int failed = 0;")
    for name, where in names:
        text.append(f'  try {{\n    {name}::run();\n  }} catch (const std::exception& e) {{\n'
                    f'    std::cout << "{where}: the block threw: " << e.what() << std::endl;\n'
                    f'    ++failed;\n  }}')
    text.append(f'  std::cout << "{len(names)} C++ blocks run" << std::endl;\n  return failed;\n}}')
    Path(out).write_text("\n".join(text) + "\n", encoding="utf-8")


def run_cpp(program, work):
    r = subprocess.run([program], cwd=work, capture_output=True, text=True, timeout=900)
    print(r.stdout, end="")
    problems = []
    if r.returncode != 0:
        problems.append(f"the C++ examples exited {r.returncode}: {r.stderr.strip()[-600:]}")
    checked = 0
    for line in r.stdout.splitlines():
        if line.startswith("CHECK\t"):
            _, where, got, expected = line.split("\t")
            checked += 1
            if not same_value(got, expected):
                problems.append(f"{where}: the value is {got}, the docs say {expected}")
    return problems, checked


def run_python(source, work, python_build):
    problems, checked = [], 0
    env = dict(os.environ, PYTHONPATH=str(python_build))
    for where, lines in blocks(source, "python"):
        # One process per block, the lines run one by one so that a failure names its line.
        file, first = where.rsplit(":", 1)
        program = ["import sys", "namespace = {}"]
        for k, line in enumerate(lines):
            if not line.strip():
                continue
            here = f"{file}:{int(first) + k}"
            code, promise = split_promise(line, "#")
            if promise is None:
                program.append(f"print({here!r}, flush=True); exec({code!r}, namespace)")
            else:
                program.append(f"print('CHECK', {here!r}, str(eval({code!r}, namespace)), "
                               f"{promise!r}, sep='\\t', flush=True)")
        r = subprocess.run([sys.executable, "-c", "\n".join(program)], cwd=work, env=env,
                           capture_output=True, text=True, timeout=900)
        if r.returncode != 0:
            ran = [l for l in r.stdout.splitlines() if l and not l.startswith("CHECK")]
            problems.append(f"{ran[-1] if ran else where}: {r.stderr.strip()[-600:]}")
        for line in r.stdout.splitlines():
            if line.startswith("CHECK\t"):
                _, here, got, expected = line.split("\t")
                checked += 1
                print(f"{here}: {got} (docs: {expected})")
                if not same_value(got, expected):
                    problems.append(f"{here}: the value is {got}, the docs say {expected}")
    return problems, checked


def run(source, program, binary, python_build, work):
    # The programs run in WORK_DIR: paths given relative to the caller's directory are made absolute.
    program, binary = str(Path(program).resolve()), str(Path(binary).resolve())
    python_build = Path(python_build).resolve()
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    # The files the examples read, made by the commands the README gives for them.
    made = subprocess.run([binary, "-q", "trace", "--triangle", "20,20 250,80 300,400", "-o",
                           "triangle.jsonl"], cwd=work, capture_output=True, text=True)
    demo = subprocess.run([binary, "-q", "demo", "-o", "demo"], cwd=work, capture_output=True,
                          text=True)
    if made.returncode or demo.returncode:
        sys.exit(f"set-up failed: {made.stderr}{demo.stderr}")
    shutil.copy(work / "demo" / "demo_scene.json", work / "scene.json")
    problems, checked = run_cpp(program, work)
    if (Path(python_build) / "scantrace").is_dir():
        more, n = run_python(source, work, python_build)
        problems += more
        checked += n
    else:
        print(f"the Python blocks are not run: {python_build} has no scantrace package")
    print(f"{checked} promised values checked, {len(problems)} problems")
    if problems:
        print("\n".join(problems))
        return 1
    if checked == 0:
        print("no promised value found: the blocks lost their `→` comments?")
        return 1
    shutil.rmtree(work, ignore_errors=True)
    return 0


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "generate":
        generate(sys.argv[2], Path(sys.argv[3]))
        return 0
    if len(sys.argv) == 7 and sys.argv[1] == "run":
        return run(Path(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5], Path(sys.argv[6]))
    sys.exit(__doc__)


if __name__ == "__main__":
    sys.exit(main())
