#!/usr/bin/env python3
"""The README's "Project layout" table names every top-level folder and every docs/*.md.

Both lists are read from what the repository holds (`git ls-files`) when the test runs, so a
folder or a document added later fails this test until the table names it, and what a user's
run leaves beside the sources (scantrace-demo/ from the README's first command, build trees) is
not part of the layout (issue 36). Outside a git checkout (a source tarball) the working tree is
listed instead. A folder is named as `name/` in the first column; a document by its file name
anywhere in the table (e.g. in the docs/ row).

usage: layout_table.py SOURCE_DIR
"""
import re
import subprocess
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


def repository_files(source):
    """The paths the repository holds, relative to SOURCE; None outside a git checkout."""
    try:
        listed = subprocess.run(["git", "-C", str(source), "ls-files", "-z"],
                                capture_output=True, text=True, check=True)
    except (OSError, subprocess.CalledProcessError):
        return None
    return [p for p in listed.stdout.split("\0") if p]


def folders_and_docs(source):
    files = repository_files(source)
    if files is None:
        # Build trees and hidden folders (.git, .ci) are not part of the layout a reader looks up.
        folders = {p.name for p in source.iterdir()
                   if p.is_dir() and not p.name.startswith((".", "build", "scantrace-demo"))}
        docs = {p.name for p in (source / "docs").glob("*.md")}
    else:
        folders = {p.split("/")[0] for p in files if "/" in p and not p.startswith(".")}
        docs = {p[len("docs/"):] for p in files
                if p.startswith("docs/") and p.endswith(".md") and p.count("/") == 1}
    return sorted(folders), sorted(docs)


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
    folders, docs = folders_and_docs(source)
    problems = [f"README.md's layout table does not name the folder `{f}/`"
                for f in folders if f not in named_folders]
    problems += [f"README.md's layout table does not name docs/{d}" for d in docs
                 if d not in table]
    problems += [f"README.md's layout table names `{f}/`, which the repository does not hold"
                 for f in sorted(named_folders) if f not in folders]
    print(f"{len(folders)} folders, {len(docs)} documents; {len(problems)} missing")
    if problems:
        print("\n".join(problems))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
