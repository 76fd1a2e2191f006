"""Student text is data: every string that a submission controls (an exception's message, its
output, a file or folder name) goes through one of these before it reaches a terminal, Markdown,
HTML, a link or a spreadsheet cell. One module, so that every place escapes the same way.

- terminal / clean: control characters (C0 but newline and tab, DEL, C1) and the bidirectional
  overrides written as visible escapes (\\x1b, \\u202e), so no text can move the cursor, set the
  window title, clear the screen or reorder what is shown;
- md_code / md_block: Markdown code spans and fences longer than any run of backticks inside, so
  no heading, link, image or HTML can be injected;
- html / href: HTML-escaped text; a relative, URL-encoded link to NAME/report.html;
- csv_cell: a cell that a spreadsheet will not take for a formula;
- fit_results: a results.json document shortened to its byte limit, saying how much was cut.
"""

import html as _html
import json
import re
import urllib.parse

# C0 controls but \t and \n, DEL, C1 controls, and the Unicode bidirectional controls (Trojan
# source: text that displays in an order other than the one it has).
_CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]")


def _escape(match):
    c = ord(match.group())
    return f"\\x{c:02x}" if c < 0x100 else f"\\u{c:04x}"


def clean(text):
    """The text with control characters written as escapes (newlines and tabs kept)."""
    return _CONTROL.sub(_escape, str(text))


def terminal(text):
    """For the grader's terminal: clean(), carriage returns included (kept out by clean too)."""
    return clean(text)


def one_line(text):
    """clean() and newlines as \\n: for a table cell, a progress line or a code span."""
    return clean(text).replace("\n", "\\n").replace("\t", "\\t")


def _longest_run(text, char="`"):
    runs = re.findall(re.escape(char) + "+", text)
    return max((len(r) for r in runs), default=0)


def md_code(text):
    """An inline code span holding the text on one line, whatever backticks it contains."""
    text = one_line(text)
    fence = "`" * (_longest_run(text) + 1)
    pad = " " if text.startswith("`") or text.endswith("`") or not text.strip() else ""
    return f"{fence}{pad}{text}{pad}{fence}"


def md_block(text):
    """A fenced code block (its own lines), the fence longer than any backtick run inside; text
    after a fence so long stays inside it even if the block is later cut short."""
    text = clean(text).rstrip("\n")
    fence = "`" * max(3, _longest_run(text) + 1)
    return f"\n{fence}text\n{text}\n{fence}\n"


def html(text):
    return _html.escape(clean(text), quote=True)


def href(name, page="report.html"):
    """A relative link to NAME/page: every character of NAME percent-encoded but letters, digits
    and _.-~, so `javascript:…` or `//host` is a path below this page, never a scheme or host."""
    return "./" + urllib.parse.quote(str(name), safe="") + "/" + page


_FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def csv_cell(value):
    """A CSV cell a spreadsheet shows as text: one starting with = + - @ tab or CR gets a leading
    apostrophe (OWASP's advice for CSV injection); numbers stay numbers."""
    if not isinstance(value, str):
        return value
    value = clean(value)
    return "'" + value if value.startswith(_FORMULA_START) else value


def _strings(node, found):
    """Every (container, key) holding a string in a JSON document."""
    items = node.items() if isinstance(node, dict) else enumerate(node)
    for key, value in items:
        if isinstance(value, str):
            found.append((node, key))
        elif isinstance(value, (dict, list)):
            _strings(value, found)
    return found


def _size(document):
    return len(json.dumps(document, indent=1).encode())


def fit_results(document, limit, list_keys=("notes",), keep=40):
    """The document (results.json) as text of at most `limit` bytes: lists of notes longer than
    `keep` entries end with "… and N more", then the longest strings are cut in half, each ending
    with the number of characters cut, until it fits."""
    if _size(document) <= limit:
        return json.dumps(document, indent=1)
    extra = document.get("extra_data", {})
    for key in list_keys:
        items = extra.get(key)
        if isinstance(items, list) and len(items) > keep:
            extra[key] = items[:keep] + [f"… and {len(items) - keep} more {key} (cut: "
                                         f"results.json is limited to {limit} bytes)"]
    while _size(document) > limit:
        where = max(_strings(document, []), key=lambda ck: len(ck[0][ck[1]]), default=None)
        if where is None or len(where[0][where[1]]) < 80:
            break
        text = where[0][where[1]]
        kept = len(text) // 2
        where[0][where[1]] = text[:kept] + f" … ({len(text) - kept} characters cut)"
    return json.dumps(document, indent=1)
