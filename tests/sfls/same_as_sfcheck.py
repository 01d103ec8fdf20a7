#!/usr/bin/env python3
"""Checks that sfls publishes exactly the diagnostics sfcheck reports.

    same_as_sfcheck.py SFLS SFCHECK --testdata DIR

Every file of the corpus below (up to 1 MB) is checked by `sfcheck --format
json` and opened in one sfls process; each diagnostic sfls publishes must be
sfcheck's, in the same order: code, severity, range, message with the hint
as its second line, notes as related information, fix-it. sfcheck's spans
count lines from 1 and bytes from 1, after a byte-order mark on the first
line; the protocol counts lines from 0 and UTF-16 units, the mark included,
and a character past a line's end means its end. The first difference of
each file is printed; any but those of KNOWN_DIFFERENCES fails the test.

A file that is not UTF-8 (a binary glTF among them) cannot travel in the
protocol's JSON (sfls would read U+FFFD for each bad byte) and is skipped.
"""

import argparse
import json
import os
import pathlib
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_transcript import SKIPPED, Session  # noqa: E402

# The folders compared, each searched recursively, and the names left out:
# the expected outputs and flags beside the inputs, and the glTF buffers.
FOLDERS = ["valid", "invalid", "pov", "gltf", "gltf-hostile", "hostile/sf",
           "hostile/instructions"]
NOT_INPUTS = (".expect", ".flags", ".md", ".bin")
MAX_SIZE = 1 << 20
SEVERITIES = {"error": 1, "warning": 2, "note": 3}
BOM = b"\xef\xbb\xbf"

# Differences known, by file under testdata: each must still be there, as
# written, so that the entry goes when sfls no longer differs.
KNOWN_DIFFERENCES = {}


def corpus(testdata):
    files = []
    for folder in FOLDERS:
        for path in sorted(pathlib.Path(testdata, folder).rglob("*")):
            if path.is_file() and not path.name.endswith(NOT_INPUTS) \
                    and path.stat().st_size <= MAX_SIZE:
                files.append(path)
    return files


def sfcheck_reports(sfcheck, files):
    """sfcheck's diagnostics of each file, by path; one run checks them all,
    each file on its own."""
    run = subprocess.run([sfcheck, "--format", "json"] +
                         [str(f) for f in files], stdout=subprocess.PIPE, check=False)
    if run.returncode not in (0, 1):
        sys.exit("sfcheck ended with %d" % run.returncode)
    return {entry["file"]: entry["diagnostics"] for entry in json.loads(run.stdout)["files"]}


class Lines:
    """Converts sfcheck's positions to the protocol's in one file's text."""

    def __init__(self, data):
        self.bom = len(BOM) if data.startswith(BOM) else 0
        self.lines = [line[:-1] if line.endswith(b"\r") else line
                      for line in data.split(b"\n")]

    def position(self, line, column):
        if line == 0:  # no line known: a glTF file's diagnostics
            return {"line": 0, "character": 0}
        if line > len(self.lines):
            last = len(self.lines) - 1
            return {"line": last, "character": self.units(self.lines[last], None)}
        text = self.lines[line - 1]
        skip = self.bom if line == 1 else 0
        return {"line": line - 1, "character": self.units(text, skip + column - 1)}

    @staticmethod
    def units(text, count):
        """UTF-16 units of `text`'s characters that start before byte `count`
        (all of them for None)."""
        units = 0
        at = 0
        for char in text.decode("utf-8"):
            if count is not None and at >= count:
                break
            units += 2 if ord(char) > 0xFFFF else 1
            at += len(char.encode("utf-8"))
        return units

    def range(self, span):
        return {"start": self.position(span["line"], span["column"]),
                "end": self.position(span["line"], span["column"] + span["length"])}


def expected_diagnostic(lines, uri, reported):
    """sfcheck's diagnostic as the protocol carries it: the fields compared."""
    message = reported["message"]
    data = {}
    if "hint" in reported:
        message += "\nhint: " + reported["hint"]
        data["hint"] = reported["hint"]
    if "fixIt" in reported:
        fix = reported["fixIt"]
        data["fixIt"] = {"range": lines.range(fix), "newText": fix["replacement"]}
    expected = {"code": reported["code"], "severity": SEVERITIES[reported["severity"]],
                "range": lines.range(reported), "message": message,
                "relatedInformation": [
                    {"location": {"uri": uri, "range": lines.range(note)},
                     "message": note["message"]} for note in reported.get("notes", [])],
                "data": data}
    return expected


def first_difference(expected, actual, where):
    """The path of the first field where `actual` differs from `expected`."""
    if isinstance(expected, dict):
        if not isinstance(actual, dict):
            return "%s: %s, not %s" % (where, json.dumps(actual), json.dumps(expected))
        for key, value in expected.items():
            found = first_difference(value, actual.get(key), where + "." + key)
            if found:
                return found
        for key in actual.keys() - expected.keys():
            return "%s.%s: %s, not absent" % (where, key, json.dumps(actual[key]))
        return None
    if isinstance(expected, list):
        if not isinstance(actual, list):
            return "%s: %s, not %s" % (where, json.dumps(actual), json.dumps(expected))
        for index, (e, a) in enumerate(zip(expected, actual)):
            found = first_difference(e, a, "%s[%d]" % (where, index))
            if found:
                return found
        if len(expected) != len(actual):
            return "%s: %d items, not %d" % (where, len(actual), len(expected))
        return None
    if expected != actual:
        return "%s: %s, not %s" % (where, json.dumps(actual), json.dumps(expected))
    return None


def published(diagnostic):
    """The fields of sfls's diagnostic that sfcheck's are compared with;
    what sfls leaves out when empty is there, empty."""
    out = {key: diagnostic.get(key) for key in ("code", "severity", "range", "message")}
    out["relatedInformation"] = diagnostic.get("relatedInformation", [])
    out["data"] = diagnostic.get("data", {})
    return out


def wait_for(session, uri, version):
    """sfls's next publishDiagnostics for `uri` (at `version`, unless None)."""
    while True:
        message = session.next_message()
        if not isinstance(message, dict):
            return "no diagnostics: %s" % (message or "the server ended")
        if message.get("method") in SKIPPED:
            continue
        params = message.get("params", {})
        if message.get("method") == "textDocument/publishDiagnostics" \
                and params.get("uri") == uri and params.get("version") == version:
            return params
        return "an unexpected message: %s" % json.dumps(message)[:300]


def compare(session, path, reported, differences):
    """Opens `path` in sfls and puts its first difference from `reported` on
    `differences`; the number of diagnostics compared, None where skipped."""
    data = path.read_bytes()
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        return None
    uri = path.absolute().as_uri()
    session.send_message({"method": "textDocument/didOpen", "params": {"textDocument": {
        "uri": uri, "languageId": "scenefile", "version": 1, "text": text}}})
    params = wait_for(session, uri, 1)
    session.send_message({"method": "textDocument/didClose",
                          "params": {"textDocument": {"uri": uri}}})
    closed = wait_for(session, uri, None)
    if isinstance(params, str) or isinstance(closed, str):
        differences.append((path, params if isinstance(params, str) else closed))
        return 0
    lines = Lines(data)
    expected = [expected_diagnostic(lines, uri, d) for d in reported]
    actual = [published(d) for d in params["diagnostics"]]
    for d, e in zip(params["diagnostics"], expected):
        href = d.get("codeDescription", {}).get("href", "")
        if not href.endswith("DIAGNOSTICS.md#" + e["code"]):
            differences.append((path, "codeDescription.href %r" % href))
            return len(reported)
    difference = first_difference(expected, actual, "diagnostics")
    if difference:
        differences.append((path, difference))
    return len(reported)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sfls")
    parser.add_argument("sfcheck")
    parser.add_argument("--testdata", required=True)
    arguments = parser.parse_args()

    started = time.monotonic()
    files = corpus(arguments.testdata)
    reports = sfcheck_reports(arguments.sfcheck, files)
    session = Session([arguments.sfls])
    differences = []
    skipped = []
    diagnostics = 0
    try:
        session.send_message({"id": 1, "method": "initialize", "params": {
            "processId": None, "rootUri": None, "capabilities": {}}})
        session.next_message()
        session.send_message({"method": "initialized", "params": {}})
        for path in files:
            count = compare(session, path, reports[str(path)], differences)
            if count is None:
                skipped.append(path.name)
            else:
                diagnostics += count
        session.send_message({"id": 2, "method": "shutdown"})
        ended = session.expect({"id": 2, "result": None})
        if not ended:
            session.send_message({"method": "exit"})
            ended = session.wait_exit(0)
        if ended:
            differences.append(("sfls", ended))
    finally:
        if session.process.poll() is None:
            session.process.kill()
            session.process.wait()
    failures = 0
    known = dict(KNOWN_DIFFERENCES)
    for path, difference in differences:
        name = os.path.relpath(path, arguments.testdata)
        if known.pop(name, None) == difference:
            print("%s: known: %s" % (path, difference))
            continue
        print("%s: %s" % (path, difference), file=sys.stderr)
        failures += 1
    for name in known:
        print("%s: no longer differs: remove it from KNOWN_DIFFERENCES" % name, file=sys.stderr)
        failures += 1
    print("%d files compared (%d diagnostics), %d not UTF-8 skipped (%s), %d known differences,"
          " %d failures, in %.1f s"
          % (len(files) - len(skipped), diagnostics, len(skipped), ", ".join(skipped),
             len(KNOWN_DIFFERENCES) - len(known), failures, time.monotonic() - started))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
