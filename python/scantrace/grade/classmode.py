"""A class: many submissions graded by a process pool (--jobs N, each submission in its own
sandbox), each into DIR/NAME/, then DIR/class.csv (one line per student) and DIR/class.html (the
score distribution, how many students have each cause, who timed out or crashed)."""

import concurrent.futures
import csv
import html
import io
import pathlib
import sys

from .causes import CATALOGUE
from .grader import grade
from .report import _write_atomic

COLUMNS = ("name", "score", "max_score", "causes", "verdicts", "error")


def _names(paths):
    """A folder name per submission, unique (two `hw1.zip` from different folders)."""
    names, seen = [], {}
    for p in paths:
        p = pathlib.Path(p)
        base = p.stem if p.suffix in (".zip", ".py") else p.name
        seen[base] = seen.get(base, 0) + 1
        names.append(base if seen[base] == 1 else f"{base}_{seen[base]}")
    return names


def _one(path, out_dir, options):
    g = grade(path, out_dir, options)
    return {"name": pathlib.Path(out_dir).name, "score": g.score, "max_score": g.max_score,
            "causes": " ".join(c.id for c in g.causes), "verdicts": " ".join(g.verdicts),
            "error": g.error, "tests": [(t.name, t.score, t.max_score) for t in g.tests]}


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
                f"{row['name']}: {row['score']:g}")
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
    with concurrent.futures.ProcessPoolExecutor(max_workers=jobs) as pool:
        futures = {pool.submit(_one, p, out / n, options): n for p, n in zip(paths, names)}
        for future in concurrent.futures.as_completed(futures):
            name = futures[future]
            try:
                row = future.result()
            except Exception as e:  # a bug of the grader: the class report still gets written
                row = {"name": name, "score": 0.0, "max_score": 0.0, "causes": "",
                       "verdicts": "", "error": f"grader error: {e}"}
            rows[name] = row
            bar.step(row)
    ordered = [rows[n] for n in names]
    _write_atomic(out / "class.csv", class_csv(ordered))
    _write_atomic(out / "class.html", class_html(ordered))
    if progress:
        print(f"{len(ordered)} submissions graded: {out / 'class.csv'}, {out / 'class.html'}",
              file=sys.stderr)
    return 1 if any(r["error"] for r in ordered) else 0


def class_csv(rows):
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, COLUMNS, lineterminator="\n")
    writer.writeheader()
    for r in rows:
        writer.writerow({k: (f"{r[k]:g}" if isinstance(r[k], float) else r[k]) for k in COLUMNS})
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
    trouble = "".join(f"<li><a href='{html.escape(r['name'])}/report.html'>"
                      f"{html.escape(r['name'])}</a>: {html.escape(r['verdicts'] or r['error'])}"
                      "</li>" for r in rows if r["verdicts"] or r["error"])
    unexplained = "".join(f"<li><a href='{html.escape(r['name'])}/report.html'>"
                          f"{html.escape(r['name'])}</a>: {r['score']:g} / {r['max_score']:g}</li>"
                          for r in _unexplained(rows))
    table = "".join(f"<tr><td><a href='{html.escape(r['name'])}/report.html'>"
                    f"{html.escape(r['name'])}</a></td><td>{r['score']:g} / {r['max_score']:g}"
                    f"</td><td>{html.escape(r['causes'])}</td></tr>" for r in rows)
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
