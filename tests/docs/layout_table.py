#!/usr/bin/env python3
"""The README's "Project layout" table names every top-level folder and every docs/*.md.

Both lists are read from the source tree when the test runs, so a folder or a document added
later fails this test until the table names it. A folder is named as `name/` in the first
column; a document by its file name anywhere in the table (e.g. in the docs/ row).

usage: layout_table.py SOURCE_DIR
"""
import re
import sys
from pathlib import Path


def layout_table(readme):
    text = readme.read_text(encoding="utf-8")
    start = text.find("## Project layout")
    if start < 0:
        sys.exit("README.md has no '## Project layout' section")
    rows = []
    for line in text[start:].split("\n")[1:]:
        if line.startswith("## "):
            break
        if line.startswith("|"):
            rows.append(line)
    return rows


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    source = Path(sys.argv[1])
    rows = layout_table(source / "README.md")
    named_folders = set()
    for row in rows:
        first = row.split("|")[1]
        named_folders.update(re.findall(r"`([^`/]+)/`", first))
    table = "\n".join(rows)
    # Build trees and hidden folders (.git, .ci) are not part of the layout a reader looks up.
    folders = sorted(p.name for p in source.iterdir()
                     if p.is_dir() and not p.name.startswith((".", "build")))
    docs = sorted(p.name for p in (source / "docs").glob("*.md"))
    problems = [f"README.md's layout table does not name the folder `{f}/`"
                for f in folders if f not in named_folders]
    problems += [f"README.md's layout table does not name docs/{d}" for d in docs
                 if d not in table]
    problems += [f"README.md's layout table names `{f}/`, which does not exist"
                 for f in sorted(named_folders) if not (source / f).is_dir()]
    print(f"{len(folders)} folders, {len(docs)} documents; {len(problems)} missing")
    if problems:
        print("\n".join(problems))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
