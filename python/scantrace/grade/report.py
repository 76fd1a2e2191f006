"""What one graded submission writes: results.json (Gradescope's autograder format, at most
100 KB), report.md and report.html, and the causes' pictures beside them (causes/ID.png)."""

import base64
import html
import json
import os
import pathlib
import tempfile

import scantrace

from . import untrusted

RESULTS_LIMIT = 100_000


def _write_atomic(path, data):
    """Writes a file whole or not at all (a temp file renamed over it)."""
    path = pathlib.Path(path)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix="." + path.name)
    with os.fdopen(fd, "wb") as f:
        f.write(data.encode("utf-8") if isinstance(data, str) else data)
    os.chmod(tmp, 0o644)
    os.replace(tmp, path)


def student_text(text):
    """Text that holds what the student's code produced (an exception's message, a value, a file
    name) as Markdown that shows it literally: a code span for one line, a fenced block for
    several (untrusted.py: control characters escaped, fences longer than any backtick run)."""
    text = str(text)
    if "\n" in text.strip("\n"):
        return "\n" + untrusted.md_block(text.strip("\n"))
    return untrusted.md_code(text.strip())


# The parts a test's `number` is grouped by ("1.1", "1.2", "2.1", … as in Gradescope's
# examples), by rubric key; deductions (no key) come last.
PARTS = (("vector_interp", "vector_interp_degenerate"),
         ("probes_flat", "probes_gouraud", "probes_pairs", "probes_beyond"),
         ("hidden_scene",), ("course_scene", "course_faces"), ("",))


def numbers(tests):
    """Each test's number: its part (among the parts present, counted from 1) and its place."""
    part_of = {k: i for i, keys in enumerate(PARTS) for k in keys}
    present = sorted({part_of.get(t.key, len(PARTS) - 1) for t in tests})
    counts, out = {}, []
    for t in tests:
        part = present.index(part_of.get(t.key, len(PARTS) - 1)) + 1
        counts[part] = counts.get(part, 0) + 1
        out.append(f"{part}.{counts[part]}")
    return out


def _cause_feedback(c):
    """What a student reads of a cause in the output of the test it cost points in."""
    return [f"**Mistake found: `{c.id}`.** {c.sentence}", "", f"**Fix:** {c.fix}", "",
            "**Evidence:** " + student_text(c.evidence)]


def test_output(t, causes):
    """A test's visible output: the causes it shows (the sentence, the fix, the evidence), then
    its own lines."""
    lines = []
    for c in causes:
        if c.test == t.name:
            lines += _cause_feedback(c) + [""]
    return "\n".join(lines + [t.output]).strip()


def results_json(graded):
    """Gradescope's results.json: tests with name, number, score, max_score, status, output
    (Markdown: each cause's sentence, fix and evidence in the test it cost points in),
    visibility; top-level score, execution_time, output; the causes under extra_data."""
    tests = [{"name": t.name, "number": n, "score": t.score, "max_score": t.max_score,
              "status": t.status, "output": test_output(t, graded.causes), "output_format": "md",
              "visibility": t.visibility,
              **({"extra_data": {"verdict": t.verdict}} if t.verdict else {})}
             for t, n in zip(graded.tests, numbers(graded.tests))]
    # A cause no test claimed (found after the last test) is shown in the top-level output,
    # which students see too.
    names = {t.name for t in graded.tests}
    loose = [line for c in graded.causes if c.test not in names for line in _cause_feedback(c)]
    result = {"score": graded.score, "execution_time": round(graded.seconds, 2),
              "output": "\n\n".join([graded.summary()] + (["\n".join(loose)] if loose else [])),
              "output_format": "md",
              "visibility": "visible",
              "stdout_visibility": "hidden", "tests": tests,
              "extra_data": {"max_score": graded.max_score,
                             "causes": [c.as_json() for c in graded.causes],
                             "notes": graded.notes}}
    text = json.dumps(result, indent=1)
    # Keep under Gradescope's limit: shorten the longest test outputs first.
    while len(text.encode()) > RESULTS_LIMIT:
        longest = max(tests, key=lambda t: len(t["output"]))
        if len(longest["output"]) < 200:
            break
        longest["output"] = longest["output"][: len(longest["output"]) // 2] + "\n… (shortened)"
        text = json.dumps(result, indent=1)
    return untrusted.fit_results(result, RESULTS_LIMIT) if len(text.encode()) > RESULTS_LIMIT \
        else text


def _cause_md(c):
    lines = [f"### `{c.id}`", "", c.sentence, "", f"**Fix:** {c.fix}", "",
             "**Evidence:** " + student_text(c.evidence)]
    if c.picture:
        lines += ["", f"![{c.id}: {c.legend}]({c.picture})"]
    return lines


def _not_graded_md(graded):
    return "\n".join([
        f"# {untrusted.md_code(graded.name)}: not graded", "",
        "This submission could not be graded: none of its code was run, so it has no score "
        "and no test results. The reason:", "", student_text(graded.error), "",
        "Fix what the reason names (a file that does not parse, a function missing or "
        "misnamed, an archive that is not a zip) and submit again.", ""])


def markdown(graded):
    if graded.error:
        return _not_graded_md(graded)
    lines = [f"# {untrusted.md_code(graded.name)}: {graded.score:g} / {graded.max_score:g}", ""]
    if graded.causes:
        lines += ["## What is wrong", ""]
        for c in graded.causes:
            lines += _cause_md(c) + [""]
    else:
        lines += ["No mistake found by the probes." if graded.score >= graded.max_score
                  else "No cause confirmed: see the tests below.", ""]
    lines += ["## Tests", "", "| | test | score | status |", "|---|---|---|---|"]
    for t, n in zip(graded.tests, numbers(graded.tests)):
        lines.append(f"| {n} | {t.name} | {t.score:g} / {t.max_score:g} | "
                     f"{t.verdict or t.status} |")
    lines.append("")
    for t in graded.tests:
        if t.output:
            lines += [f"### {t.name}", "", t.output, ""]
    if graded.notes:
        lines += ["## Notes", untrusted.md_block("\n".join(graded.notes))]
    return "\n".join(lines)


def _inline(text):
    """Markdown's `code` as <code>, the rest escaped."""
    parts = html.escape(text).split("`")
    return "".join(f"<code>{p}</code>" if i % 2 else p for i, p in enumerate(parts))


def html_report(graded, directory):
    if graded.error:
        return (f"<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>"
                f"{html.escape(graded.name)}: not graded</title></head><body>"
                f"<h1>{html.escape(graded.name)}: not graded</h1><p>This submission could not be "
                "graded: none of its code was run, so it has no score and no test results. The "
                f"reason:</p><pre>{html.escape(graded.error)}</pre></body></html>\n")
    rows = "".join(f"<tr><td>{_inline(t.name)}</td><td>{t.score:g} / {t.max_score:g}</td>"
                   f"<td class='{t.status}'>{html.escape(t.verdict or t.status)}</td></tr>"
                   for t in graded.tests)
    causes = ""
    for c in graded.causes:
        picture = ""
        if c.picture:
            data = base64.b64encode((directory / c.picture).read_bytes()).decode()
            picture = (f"<img alt='{c.id}' src='data:image/png;base64,{data}'>"
                       f"<p class='legend'>{html.escape(c.legend)}</p>")
        causes += (f"<section><h3><code>{c.id}</code></h3><p>{_inline(c.sentence)}</p>"
                   f"<p><b>Fix:</b> {_inline(c.fix)}</p><p><b>Evidence:</b> "
                   f"{_inline(c.evidence)}</p>{picture}</section>")
    details = "".join(f"<h3>{_inline(t.name)}</h3><pre>{html.escape(t.output)}</pre>"
                      for t in graded.tests if t.output)
    return f"""<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>{html.escape(graded.name)}: grade</title>
<style>body{{font-family:sans-serif;max-width:60em;margin:2em auto}}
td,th{{padding:.2em .8em;border-bottom:1px solid #ddd}}.failed{{color:#b00}}.passed{{color:#070}}
img{{image-rendering:pixelated;border:1px solid #ccc}}.legend{{font-size:small;color:#666}}
pre{{white-space:pre-wrap;background:#f6f6f6;padding:.5em}}</style></head><body>
<h1>{html.escape(graded.name)}: {graded.score:g} / {graded.max_score:g}</h1>
<h2>What is wrong</h2>{causes or "<p>No cause confirmed.</p>"}
<h2>Tests</h2><table><tr><th>test</th><th>score</th><th>status</th></tr>{rows}</table>
{details}
</body></html>
"""


def write(graded, directory):
    directory = pathlib.Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    for c in graded.causes:
        if c.picture_pixels is not None:
            (directory / "causes").mkdir(exist_ok=True)
            c.picture = f"causes/{c.id}.png"
            scantrace.write_png(c.picture_pixels, str(directory / c.picture))
    _write_atomic(directory / "report.md", markdown(graded))
    _write_atomic(directory / "report.html", html_report(graded, directory))
    _write_atomic(directory / "results.json", results_json(graded))
