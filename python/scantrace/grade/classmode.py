"""A class: many submissions graded by a process pool (--jobs N, each submission in its own
sandbox), each into DIR/NAME/, then DIR/class.csv (one line per student) and DIR/class.html (the
score distribution, how many students have each cause, who timed out or crashed)."""

import csv
import html
import io
import json
import multiprocessing
import multiprocessing.connection
import os
import pathlib
import resource
import signal
import statistics
import sys
import traceback

from . import battery, report, untrusted
from .causes import CATALOGUE
from .grader import Graded, grade
from .report import _write_atomic

COLUMNS = ("name", "score", "max_score", "causes", "verdicts", "error")


def _safe_name(name):
    """A folder name of this output: never empty, `.`, `..`, hidden or the class report's own
    file names (a folder `class.csv/` would stop it being written), at most 120 characters."""
    name = name[:120]
    if name in ("class.csv", "class.html"):
        return "_" + name
    return "_" + name[1:] if not name or name.startswith(".") else name


def _own_name(p):
    return p.stem if p.suffix in (".zip", ".py") and not p.is_dir() else p.name


def _names(paths):
    """A folder name per submission, unique: its own name (hw1 for a/hw1.py), with its folders'
    names in front while it equals another's (a/hw1.py, b/hw1.py: a-hw1, b-hw1), numbered only
    when the whole paths agree."""
    items = [pathlib.Path(os.path.abspath(p)) for p in paths]
    parents = [list(p.parent.parts[1:]) for p in items]
    names = [_own_name(p) for p in items]
    depth = [0] * len(items)
    while True:
        groups = {}
        for i, n in enumerate(names):
            groups.setdefault(n, []).append(i)
        clashing = [i for g in groups.values() if len(g) > 1 for i in g
                    if depth[i] < len(parents[i])]
        if not clashing:
            break
        for i in clashing:
            depth[i] += 1
            names[i] = "-".join(parents[i][len(parents[i]) - depth[i]:] + [_own_name(items[i])])
    names = [_safe_name(n) for n in names]
    taken, unique = set(names), []
    for n in names:
        if n in unique:
            k = 2
            while f"{n}_{k}" in taken:
                k += 1
            n = f"{n}_{k}"
            taken.add(n)
        unique.append(n)
    return unique


def _one(path, out_dir, options):
    g = grade(path, out_dir, options)
    return {"name": pathlib.Path(out_dir).name, "score": g.score, "max_score": g.max_score,
            "causes": " ".join(c.id for c in g.causes), "verdicts": " ".join(g.verdicts),
            "error": g.error[:2000],
            "tests": [(t.name, t.score, t.max_score) for t in g.tests]}


def _error_row(name, error):
    return {"name": name, "score": 0.0, "max_score": 0.0, "causes": "", "verdicts": "",
            "error": error, "tests": []}


def not_graded(name, out_dir, error):
    """A results.json (and reports) saying why a submission has no grade; never raises."""
    try:
        report.write(Graded(name, [], [], [], 0.0, error=error), out_dir)
    except Exception:  # noqa: BLE001 - the folder itself may be what failed
        pass
    return _error_row(name, error)


def _worker(path, out_dir, options, conn):
    """One submission in a process of its own: whatever its student's code does to this process
    (`os.kill(os.getppid(), SIGKILL)` without the sandbox), only this submission is lost."""
    try:
        row = _one(path, out_dir, options)
    except Exception as e:  # a bug of the grader: the class report still gets written
        traceback.print_exc()
        row = not_graded(pathlib.Path(out_dir).name, out_dir, f"grader error: {e}"[:2000])
    # The grader's own CPU for this submission: this process alone (a forked process starts at
    # zero); the student's code runs in the sandbox's children and is not counted.
    own = resource.getrusage(resource.RUSAGE_SELF)
    row["grader_cpu"] = own.ru_utime + own.ru_stime
    conn.send_bytes(json.dumps(row).encode())   # JSON, not a pickle: read by the parent
    conn.close()


def _well_formed(row, name):
    return (isinstance(row, dict) and set(COLUMNS) <= set(row) and row["name"] == name
            and all(isinstance(row[k], (int, float)) for k in ("score", "max_score"))
            and all(isinstance(row[k], str) for k in ("causes", "verdicts", "error")))


def _finish(process, conn, name, out_dir):
    """The worker's row; when it died without one, a row and a results.json that say so."""
    row = None
    try:
        if conn.poll(5):
            row = json.loads(conn.recv_bytes(1 << 20))
    except (EOFError, OSError, ValueError):
        row = None
    conn.close()
    process.join(10)
    if _well_formed(row, name):
        row["causes"] = " ".join(c for c in row["causes"].split() if c in CATALOGUE)
        return row
    code = process.exitcode
    how = f"killed by {signal.Signals(-code).name}" if code and code < 0 else \
        f"exited with status {code}"
    return not_graded(name, out_dir, f"the grader's process for this submission {how} before "
                      "it finished (its code may have killed it); no other submission is affected")


def _grade_all(jobs_list, options, jobs, bar, rows):
    context = multiprocessing.get_context("fork")
    waiting, running = list(jobs_list), {}
    try:
        while waiting or running:
            while waiting and len(running) < jobs:
                path, name, out_dir = waiting.pop(0)
                receive, send = context.Pipe(duplex=False)
                process = context.Process(target=_worker, args=(path, out_dir, options, send))
                process.start()
                send.close()
                running[process.sentinel] = (process, receive, name, out_dir)
            # A row is a few KB (the error is cut at 2000 characters): it fits in the pipe, so
            # waiting for the worker's exit before reading cannot block it.
            for sentinel in multiprocessing.connection.wait(list(running)):
                process, receive, name, out_dir = running.pop(sentinel)
                rows[name] = _finish(process, receive, name, out_dir)
                bar.step(rows[name])
    finally:
        for process, receive, name, out_dir in running.values():
            process.terminate()   # SIGTERM: each removes its temporary folders
        for process, *_ in running.values():
            process.join(10)
            if process.is_alive():
                process.kill()


class _Progress:
    def __init__(self, total, enabled):
        self.total, self.done, self.enabled = total, 0, enabled
        self.tty = enabled and sys.stderr.isatty()

    def step(self, row):
        self.done += 1
        if not self.enabled:
            return
        filled = 30 * self.done // self.total
        text = (f"[{'#' * filled}{'.' * (30 - filled)}] {self.done}/{self.total} "
                f"{untrusted.one_line(row['name'])}: {row['score']:g}")
        print(("\r" + text.ljust(79)) if self.tty else text, end="" if self.tty else "\n",
              file=sys.stderr, flush=True)
        if self.tty and self.done == self.total:
            print(file=sys.stderr)


def run(paths, out, options, jobs, progress=True):
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    names = _names(paths)
    rows = {}
    bar = _Progress(len(paths), progress)
    battery.warm_up()   # once here, shared by the forked workers
    try:
        _grade_all([(p, n, out / n) for p, n in zip(paths, names)], options, jobs, bar, rows)
    finally:
        # Always written, interrupted or not: the rows known, the others saying why they are not.
        ordered = [rows.get(n) or _error_row(n, "not graded: the grader was interrupted")
                   for n in names]
        _write_atomic(out / "class.csv", class_csv(ordered))
        _write_atomic(out / "class.html", class_html(ordered))
    if progress:
        print(f"{len(ordered)} submissions graded: {out / 'class.csv'}, {out / 'class.html'}",
              file=sys.stderr)
        print(own_time_line(ordered), file=sys.stderr)
    return 1 if any(r["error"] for r in ordered) else 0


def own_time_line(rows):
    """The grader's own CPU per submission (its workers', the students' code excluded)."""
    cpu = [r["grader_cpu"] for r in rows if isinstance(r.get("grader_cpu"), (int, float))]
    if not cpu:
        return "the grader's own CPU per submission: not measured"
    return (f"the grader's own CPU per submission (the students' code excluded): median "
            f"{statistics.median(cpu):.2f} s, largest {max(cpu):.2f} s, over {len(cpu)}")


def class_csv(rows):
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, COLUMNS, lineterminator="\n")
    writer.writeheader()
    for r in rows:
        writer.writerow({k: (f"{r[k]:g}" if isinstance(r[k], float) else untrusted.csv_cell(r[k]))
                         for k in COLUMNS})
    return buffer.getvalue()


def _histogram(rows, bins=10):
    scores = [r["score"] / r["max_score"] for r in rows if r["max_score"]]
    counts = [0] * bins
    for s in scores:
        counts[min(int(s * bins), bins - 1)] += 1
    top = max(counts) or 1
    return "".join(f"<tr><td>{100 * k // bins}–{100 * (k + 1) // bins} %</td><td>"
                   f"<div class='bar' style='width:{20 * c / top:.1f}em'></div> {c}</td></tr>"
                   for k, c in enumerate(counts))


# A submission graded below this share of the maximum with no cause named and no verdict: the
# grader could not say why, so a teaching assistant should look (class.html lists it).
LOW_SCORE = 0.5


def _breakdown(rows):
    """Each student's points per test, one column a test (its name in the header's title)."""
    names = []
    for r in rows:
        names += [n for n, _, _ in r.get("tests", ()) if n not in names]
    head = "".join(f"<th title='{html.escape(n)}'>{k + 1}</th>" for k, n in enumerate(names))
    legend = "".join(f"<li>{k + 1}: {html.escape(n)}</li>" for k, n in enumerate(names))
    body = ""
    for r in rows:
        got = {n: (s, m) for n, s, m in r.get("tests", ())}
        cells = "".join(f"<td class='{'low' if n in got and got[n][0] < got[n][1] else ''}'>"
                        + (f"{got[n][0]:g}/{got[n][1]:g}" if n in got else "–") + "</td>"
                        for n in names)
        body += f"<tr><td>{html.escape(r['name'])}</td>{cells}</tr>"
    return (f"<table><tr><th>submission</th>{head}</tr>{body}</table>"
            f"<ol class='legend'>{legend}</ol>")


def _unexplained(rows):
    """Submissions scoring below LOW_SCORE of the maximum with no cause, verdict or error."""
    return [r for r in rows if r["max_score"] and r["score"] < LOW_SCORE * r["max_score"]
            and not (r["causes"] or r["verdicts"] or r["error"])]


def class_html(rows):
    counts = {}
    for r in rows:
        for c in r["causes"].split():
            counts[c] = counts.get(c, 0) + 1
    causes = "".join(f"<tr><td><code>{c}</code></td><td>{n}</td><td>"
                     f"{html.escape(CATALOGUE[c][0].format(detail='…'))}</td></tr>"
                     for c, n in sorted(counts.items(), key=lambda kv: -kv[1]))
    trouble = "".join(f"<li><a href='{untrusted.html(untrusted.href(r['name']))}'>"
                      f"{untrusted.html(r['name'])}</a>: "
                      f"{untrusted.html(r['verdicts'] or r['error'])}"
                      "</li>" for r in rows if r["verdicts"] or r["error"])
    unexplained = "".join(f"<li><a href='{untrusted.html(untrusted.href(r['name']))}'>"
                          f"{untrusted.html(r['name'])}</a>: {r['score']:g} / {r['max_score']:g}</li>"
                          for r in _unexplained(rows))
    table = "".join(f"<tr><td><a href='{untrusted.html(untrusted.href(r['name']))}'>"
                    f"{untrusted.html(r['name'])}</a></td><td>{r['score']:g} / {r['max_score']:g}"
                    f"</td><td>{untrusted.html(r['causes'])}</td></tr>" for r in rows)
    return f"""<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>Class report</title>
<style>body{{font-family:sans-serif;max-width:60em;margin:2em auto}}
td,th{{padding:.2em .8em;border-bottom:1px solid #ddd;text-align:left}}
.bar{{display:inline-block;height:.9em;background:#48c}}.low{{color:#b00}}
.legend{{font-size:small;color:#666}}</style></head><body>
<h1>Class report: {len(rows)} submissions</h1>
<h2>Scores</h2><table>{_histogram(rows)}</table>
<h2>Causes</h2><table><tr><th>cause</th><th>students</th><th>what</th></tr>{causes}</table>
<h2>Timed out, crashed, forbidden or not graded</h2><ul>{trouble or "<li>none</li>"}</ul>
<h2>Low score, no cause</h2><p>Below {LOW_SCORE:.0%} of the maximum with no cause named and no
verdict: the grader could not say why; look at these.</p><ul>{unexplained or "<li>none</li>"}</ul>
<h2>Per test</h2>{_breakdown(rows)}
<h2>Students</h2><table><tr><th>submission</th><th>score</th><th>causes</th></tr>{table}</table>
</body></html>
"""
