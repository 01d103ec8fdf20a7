#!/usr/bin/env python3
"""The library speaks in its own words: no source of libscene/ or
include/scenefile/ names a tool (sfcheck, sfconvert, sfrender, sfbuild)
anywhere, nor a tool's flag (--max-file-size, -o) in a string or a comment.
A diagnostic that a setting can cure names it as data (scene::Remedy), and
each front end says it in its own terms (docs/DIAGNOSTICS.md, "Remedies").

Tests (*_test.cpp) are held to the same rule, but may quote the POV-Ray
format's exact-value marker, which the files they read and write carry.

    check_library_words.py SOURCE_DIR
"""

import pathlib
import re
import sys

# A flag starts a word: after a space, a quote, a bracket or a backquote.
FLAG = re.compile(r"(?:^|(?<=[\s\"'(`\[]))(--[a-z][a-z0-9-]*|-o\b)")

# A tool's name is a word of its own, in code, strings and comments.
TOOL = re.compile(r"\bsf(?:check|convert|render|build)\b")

# The file format's words, which the files the POV-Ray writer wrote carry and
# every conversion keeps byte for byte: its header (which render the file
# reproduces) and the marker of its exact-value comments. Each is one named
# literal, exempt where it is defined and nowhere else.
OUTPUT_TEXT = {
    ("libscene/formats/pov/pov_writer.cpp",
     r'"// Written by sfconvert: the picture of sfrender "'),
    ("libscene/formats/pov/pov_writer.cpp", r'"--fov "'),
    ("libscene/formats/pov/pov_writer.cpp", r'" --width "'),
    ("libscene/formats/pov/pov_writer.cpp", r'" --height "'),
    ("libscene/formats/pov/pov_writer.cpp",
     r'".\n// Render it with linear output, as sfrender writes:\n//   povray +W"'),
    ("libscene/formats/pov/pov_lexer.h", r'"// sfconvert:"'),
}
# What a test may quote: the marker that starts each exact-value comment.
TEST_TEXT = "// sfconvert:"


def words(text):
    """Each string literal and comment of C++ source, with its line number."""
    i, line, n = 0, 1, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            end = text.find("\n", i)
            end = n if end < 0 else end
            yield line, text[i:end]
            i = end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            yield line, text[i:end]
            line += text.count("\n", i, end)
            i = end
        elif text.startswith('R"', i) and not (i and (text[i - 1].isalnum() or text[i - 1] == "_")):
            open_end = text.find("(", i)
            delimiter = ")" + text[i + 2:open_end] + '"'
            end = text.find(delimiter, open_end)
            end = n if end < 0 else end + len(delimiter)
            yield line, text[i:end]
            line += text.count("\n", i, end)
            i = end
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            yield line, text[i:j + 1]
            i = j + 1
        else:
            if c == "\n":
                line += 1
            i += 1


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    failures = 0
    sources = sorted(p for folder in ("libscene", "include/scenefile")
                     for p in (root / folder).rglob("*")
                     if p.suffix in (".h", ".cpp", ".def"))
    for path in sources:
        name = path.relative_to(root).as_posix()
        text = path.read_text(encoding="utf-8", errors="replace")
        # Exempt literals are blanked (newlines kept, so line numbers hold).
        for exempt_name, literal in OUTPUT_TEXT:
            if exempt_name == name:
                text = text.replace(literal, '""')
        if name.endswith("_test.cpp"):
            text = text.replace(TEST_TEXT, "")
        for number, source_line in enumerate(text.splitlines(), 1):
            for tool in TOOL.findall(source_line):
                print(f"FAIL: {name}:{number} names the tool {tool}: {source_line.strip()}",
                      file=sys.stderr)
                failures += 1
        for line, piece in words(text):
            for flag in FLAG.findall(piece):
                print(f"FAIL: {name}:{line} names the flag {flag}: {piece.strip()}",
                      file=sys.stderr)
                failures += 1
    if failures:
        print(f"FAIL: {failures} tools or flags named in the library; say it in the "
              "library's terms, give a diagnostic a scene::Remedy and let the front "
              "end say the setting", file=sys.stderr)
        return 1
    print(f"{len(sources)} library sources name no tool and no flag")
    return 0


if __name__ == "__main__":
    sys.exit(main())
