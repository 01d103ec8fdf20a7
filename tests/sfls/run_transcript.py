#!/usr/bin/env python3
"""Runs sfls through a recorded JSON-RPC session and checks its answers.

    run_transcript.py SFLS TRANSCRIPT --testdata DIR --source DIR

A transcript holds one item a line (blank lines and lines starting with #
are skipped):

    --> JSON        a message the client sends, framed with Content-Length
                    ("jsonrpc": "2.0" is added where it is left out)
    <-- JSON        the server's next message: every key given must be there
                    with an equal value, arrays of the same length matched
                    element by element; window/logMessage and $/progress
                    messages are skipped unless they are what is expected
    ==> "STRING"    raw bytes (a JSON string, each character a byte), sent
                    as they are: a bad header, a length no bytes follow
    !close          closes the server's standard input
    !exit N         the server ends with exit status N, with no message left
                    unread but those skipped above
    !stderr REGEX   what the server wrote on standard error matches REGEX
                    (once it has ended)

${TESTDATA} stands for the testdata folder, ${SOURCE} for the source tree
and ${TMP} for a fresh temporary folder, in every line.
"""

import argparse
import json
import queue
import re
import shutil
import subprocess
import sys
import tempfile
import threading

TIMEOUT = 20.0
SKIPPED = {"window/logMessage", "$/progress"}


def read_messages(stream, out):
    """Puts each framed message of `stream` on `out`; None at the end."""
    while True:
        length = None
        while True:
            line = stream.readline()
            if not line:
                out.put(None)
                return
            line = line.rstrip(b"\r\n")
            if not line:
                break
            name, _, value = line.partition(b":")
            if name.strip().lower() == b"content-length":
                length = int(value.strip())
        body = stream.read(length)
        try:
            out.put(json.loads(body))
        except ValueError:
            out.put({"unparsable": body.decode("utf-8", "replace")})


def matches(expected, actual):
    if isinstance(expected, dict):
        return isinstance(actual, dict) and all(
            key in actual and matches(value, actual[key]) for key, value in expected.items())
    if isinstance(expected, list):
        return (isinstance(actual, list) and len(expected) == len(actual)
                and all(matches(e, a) for e, a in zip(expected, actual)))
    if isinstance(expected, bool) or isinstance(actual, bool):
        return expected is actual
    return expected == actual


class Session:
    def __init__(self, command):
        self.process = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE)
        self.messages = queue.Queue()
        self.stderr = []
        threading.Thread(target=read_messages, args=(self.process.stdout, self.messages),
                         daemon=True).start()
        threading.Thread(target=lambda: self.stderr.append(self.process.stderr.read()),
                         daemon=True).start()

    def send(self, data):
        try:
            self.process.stdin.write(data)
            self.process.stdin.flush()
        except BrokenPipeError:
            pass

    def send_message(self, message):
        """Sends `message` framed with its Content-Length ("jsonrpc" added where left out)."""
        message.setdefault("jsonrpc", "2.0")
        body = json.dumps(message).encode("utf-8")
        self.send(b"Content-Length: %d\r\n\r\n" % len(body) + body)

    def next_message(self):
        try:
            return self.messages.get(timeout=TIMEOUT)
        except queue.Empty:
            return "nothing within %g s" % TIMEOUT

    def expect(self, expected):
        while True:
            actual = self.next_message()
            if isinstance(actual, dict) and matches(expected, actual):
                return None
            if isinstance(actual, dict) and actual.get("method") in SKIPPED:
                continue
            return "expected\n  %s\nreceived\n  %s" % (json.dumps(expected), json.dumps(actual))

    def wait_exit(self, status):
        try:
            self.process.stdin.close()
        except BrokenPipeError:
            pass
        try:
            got = self.process.wait(timeout=TIMEOUT)
        except subprocess.TimeoutExpired:
            self.process.kill()
            return "the server did not end within %g s" % TIMEOUT
        while True:
            left = self.next_message()
            if left is None:
                break
            if not isinstance(left, dict) or left.get("method") not in SKIPPED:
                return "a message was left unread: %s" % json.dumps(left)
        if got != status:
            return "the server ended with %d, not %d" % (got, status)
        return None

    def stderr_text(self):
        self.process.wait(timeout=TIMEOUT)
        for _ in range(100):
            if self.stderr:
                break
            threading.Event().wait(0.05)
        return b"".join(self.stderr).decode("utf-8", "replace")


def run(arguments):
    tmp = tempfile.mkdtemp(prefix="sfls-transcript-")
    substitutions = {"${TESTDATA}": arguments.testdata, "${SOURCE}": arguments.source,
                     "${TMP}": tmp}
    session = Session([arguments.sfls])
    failure = None
    try:
        with open(arguments.transcript, encoding="utf-8") as lines:
            for number, line in enumerate(lines, 1):
                line = line.strip()
                if not line or line.startswith("#"):
                    continue
                for name, value in substitutions.items():
                    line = line.replace(name, value)
                kind, _, rest = line.partition(" ")
                if kind == "-->":
                    session.send_message(json.loads(rest))
                elif kind == "<--":
                    failure = session.expect(json.loads(rest))
                elif kind == "==>":
                    session.send(json.loads(rest).encode("latin-1"))
                elif kind == "!close":
                    session.process.stdin.close()
                elif kind == "!exit":
                    failure = session.wait_exit(int(rest))
                elif kind == "!stderr":
                    text = session.stderr_text()
                    if not re.search(rest, text):
                        failure = "standard error does not match %r:\n%s" % (rest, text)
                else:
                    failure = "unknown line kind %r" % kind
                if failure:
                    print("%s:%d: %s" % (arguments.transcript, number, failure), file=sys.stderr)
                    return 1
        return 0
    finally:
        if session.process.poll() is None:
            session.process.kill()
            session.process.wait()
        shutil.rmtree(tmp, ignore_errors=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sfls")
    parser.add_argument("transcript")
    parser.add_argument("--testdata", required=True)
    parser.add_argument("--source", required=True)
    return run(parser.parse_args())


if __name__ == "__main__":
    sys.exit(main())
