#!/usr/bin/env python3
"""The docs' limits, and that every section they or the code cite exists.

    check_docs.py limits SOURCE_DIR
    check_docs.py citations SOURCE_DIR

limits: no docs/*.md over 500 lines but FORMATS.md (the format's reference),
and no table cell over 300 characters, so that each page answers its
questions and each table can be read. docs/history/ (dated runs, kept as
they were) is exempt.

citations: a citation names a page and a heading, as in
`docs/RENDERING.md, "Cost"` or `RENDERING.md ("Cost")`, possibly wrapped
over comment lines; or it links to one, as in `[x](RENDERING.md#cost)`.
Each must name a page that exists and a heading of it (any level). The
heading must match exactly (spaces aside): a citation that only nearly
matches is one that went stale. Files tracked by git are read; docs/history/
is exempt, since it quotes what was true then.
"""

import os
import re
import subprocess
import sys

MAX_LINES = 500
MAX_CELL = 300
LINE_LIMIT_EXEMPT = {"FORMATS.md"}
HISTORY = "docs/history/"

# A page (or a Markdown link to one), then a heading in quotes: `, "..."`,
# ` "..."` or ` ("...")`.
QUOTED = re.compile(r'((?:[\w.-]+/)*[A-Z][A-Z_]*\.md)\)?(?:,\s*\(?|\s*\(|\s+\(?)\s*\\?"([^"\\;{}]{1,120})\\?"')
# A Markdown link to a heading: `(PAGE.md#anchor)`.
ANCHOR = re.compile(r"\]\(((?:[\w.-]+/)*[A-Z][A-Z_]*\.md)#([\w-]+)\)")
# What a comment's next line starts with, removed when lines are joined so
# that a citation wrapped over two comment lines reads as one.
COMMENT_LEAD = re.compile(r"\n[ \t]*(?:///?|#|\*|--|;)?[ \t]*")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def tracked_files(root):
    out = subprocess.run(["git", "-C", root, "ls-files", "-z"], capture_output=True,
                         check=True).stdout.decode()
    return [f for f in out.split("\0") if f]


def docs_pages(root):
    docs = os.path.join(root, "docs")
    return sorted(f for f in os.listdir(docs) if f.endswith(".md"))


def table_cells(line):
    """The cells of a Markdown table row, split at `|` outside code spans."""
    cells, cell, in_code = [], [], False
    body = line.strip()
    body = body[1:] if body.startswith("|") else body
    body = body[:-1] if body.endswith("|") and not body.endswith("\\|") else body
    i = 0
    while i < len(body):
        c = body[i]
        if c == "\\" and i + 1 < len(body):
            cell.append(body[i:i + 2])
            i += 2
            continue
        if c == "`":
            in_code = not in_code
        if c == "|" and not in_code:
            cells.append("".join(cell))
            cell = []
        else:
            cell.append(c)
        i += 1
    cells.append("".join(cell))
    return [c.strip() for c in cells]


def check_limits(root):
    failures = []
    for page in docs_pages(root):
        path = os.path.join(root, "docs", page)
        with open(path, encoding="utf-8") as f:
            lines = f.read().split("\n")
        if lines and lines[-1] == "":
            lines.pop()
        if page not in LINE_LIMIT_EXEMPT and len(lines) > MAX_LINES:
            failures.append(f"docs/{page}: {len(lines)} lines, more than {MAX_LINES}")
        fenced = False
        for number, line in enumerate(lines, 1):
            if line.lstrip().startswith("```"):
                fenced = not fenced
            if fenced or not line.lstrip().startswith("|"):
                continue
            for cell in table_cells(line):
                if len(cell) > MAX_CELL:
                    failures.append(f"docs/{page}:{number}: a table cell of {len(cell)} "
                                    f"characters, more than {MAX_CELL}: {cell[:60]}...")
    return failures


def headings(path):
    """The page's headings, spaces collapsed, outside fenced code."""
    found, fenced = set(), False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.lstrip().startswith("```"):
                fenced = not fenced
                continue
            match = None if fenced else HEADING.match(line)
            if match:
                found.add(" ".join(match.group(2).split()))
    return found


def anchor_of(heading):
    """GitHub's anchor for a heading: lower case, punctuation dropped,
    spaces as hyphens."""
    text = re.sub(r"[^\w\- ]", "", heading.lower())
    return text.replace(" ", "-")


def resolve(root, citing, page):
    """The cited page's path in the tree: as written from the root, beside
    the citing file, or under docs/ for a bare name."""
    candidates = [page, os.path.join(os.path.dirname(citing), page)]
    if "/" not in page:
        candidates.append(os.path.join("docs", page))
    for candidate in candidates:
        candidate = os.path.normpath(candidate)
        if os.path.isfile(os.path.join(root, candidate)):
            return candidate
    return None


def check_citations(root):
    failures, count, cache = [], 0, {}
    for name in tracked_files(root):
        if name.startswith(HISTORY) or name.startswith("third_party/"):
            continue
        path = os.path.join(root, name)
        if not os.path.isfile(path):
            continue  # deleted in the work tree, not yet in the index
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except (UnicodeDecodeError, OSError):
            continue
        if ".md" not in text:
            continue
        joined = COMMENT_LEAD.sub(" ", text)
        cites = [(m, False) for m in QUOTED.finditer(joined)]
        cites += [(m, True) for m in ANCHOR.finditer(text)]
        for match, is_anchor in cites:
            page, section = match.group(1), " ".join(match.group(2).split())
            count += 1
            target = resolve(root, name, page)
            if target is None:
                failures.append(f"{name}: cites {page}, which does not exist")
                continue
            if target not in cache:
                cache[target] = headings(os.path.join(root, target))
            known = cache[target]
            if is_anchor:
                if section not in {anchor_of(h) for h in known}:
                    failures.append(f"{name}: links to {page}#{section}, no heading of {target}")
            elif section not in known:
                failures.append(f'{name}: cites {page}, "{section}", no heading of {target}')
    return failures, count


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("limits", "citations"):
        sys.exit(__doc__)
    root = sys.argv[2]
    if sys.argv[1] == "limits":
        failures = check_limits(root)
        summary = f"{len(docs_pages(root))} pages"
    else:
        failures, count = check_citations(root)
        summary = f"{count} citations"
    for failure in failures:
        print(f"FAIL: {failure}", file=sys.stderr)
    if failures:
        sys.exit(f"FAIL: {len(failures)} of the docs' {sys.argv[1]} broken")
    print(f"ok: {summary}")


if __name__ == "__main__":
    main()
