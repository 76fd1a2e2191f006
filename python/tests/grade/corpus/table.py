"""The corpus table of docs/grading.md, from expected.toml and (optionally) a results file that
test_grade_corpus.py writes (name -> score fraction, causes found, error):

    python3 python/tests/grade/corpus/table.py [corpus-results.json]
"""

import json
import pathlib
import sys
import tomllib

HERE = pathlib.Path(__file__).resolve().parent


def load_expected(path=HERE / "expected.toml"):
    with open(path, "rb") as f:
        return tomllib.load(f)


def _band(e):
    lo, hi = round(100 * e["min"]), round(100 * e["max"], 1)
    return "100 %" if lo == hi == 100 else f"{lo}–{hi:g} %"


def _causes(ids, new=False):
    if not ids:
        return "none"
    return ", ".join(f"`{c}`" + (" (new)" if new else "") for c in ids)


def markdown(expected, results=None):
    head = "| submission | style | expected causes | band |"
    rule = "|---|---|---|---|"
    if results is not None:
        head += " score | causes found |"
        rule += "---:|---|"
    lines = [head, rule]
    for name, e in expected.items():
        row = (f"| `{name}` | {e['style']} | {_causes(e['causes'], e.get('new', False))} "
               f"| {_band(e)} |")
        if results is not None:
            r = results.get(name)
            if r is None:
                row += " – | not run |"
            elif r.get("error"):
                row += f" 0 % | not graded: {r['error'][:60]} |"
            else:
                row += f" {100 * r['fraction']:.0f} % | {_causes(r['causes'])} |"
        lines.append(row.replace("\n", " "))
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    res = json.loads(pathlib.Path(sys.argv[1]).read_text()) if len(sys.argv) > 1 else None
    sys.stdout.write(markdown(load_expected(), res))
