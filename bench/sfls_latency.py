#!/usr/bin/env python3
"""sfls's latency and memory, measured by a scripted client (the standard
library only): bench/sfls_bench.sh runs it on generated scenes.

    sfls_latency.py [--runs N] [--timeout S] SFLS FILE

Starts SFLS, opens FILE, waits for its first diagnostics, then N times:

  diagnostics   a one-character edit that makes an error (a record's name
                loses its last letter), then the edit that puts it back: the
                time from each didChange to the publishDiagnostics of that
                version (with an error, then with none);
  requests      hover (on a matrix number), completion (where a record
                starts) and documentSymbol, each answered while idle and
                sent right after an edit, while that edit's check runs.

Edits are incremental where the server offers it (a range of one
character), else the whole text. It prints "key: value" lines: seconds
(median and max over the N runs of each), the document's size in bytes,
and sfls's peak resident memory (VmHWM of /proc/PID/status). Exits 1 when
the server fails, answers with an error, or does not answer in time.
"""

import argparse
import json
import os
import queue
import statistics
import subprocess
import sys
import threading
import time


class Failure(Exception):
    pass


class Client:
    """One sfls process: requests, notifications, and a thread that reads
    its messages into a queue, each stamped with the time it arrived."""

    def __init__(self, command, timeout):
        self.process = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        self.timeout = timeout
        self.messages = queue.Queue()
        self.next_id = 0
        self.pending = []  # messages read while waiting for another
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        stream = self.process.stdout
        while True:
            length = None
            while True:
                line = stream.readline()
                if not line:
                    self.messages.put((time.perf_counter(), None))
                    return
                line = line.strip()
                if not line:
                    break
                name, _, value = line.partition(b":")
                if name.strip().lower() == b"content-length":
                    length = int(value)
            body = stream.read(length) if length is not None else b""
            self.messages.put((time.perf_counter(), json.loads(body)))

    def send(self, message):
        message["jsonrpc"] = "2.0"
        body = json.dumps(message, separators=(",", ":")).encode()
        # Timed from before the write: a big document's transfer counts.
        sent = time.perf_counter()
        try:
            self.process.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
            self.process.stdin.flush()
        except OSError as error:
            raise Failure(f"sfls no longer reads its input ({self._status()}): {error}")
        return sent

    def notify(self, method, params):
        return self.send({"method": method, "params": params})

    def request(self, method, params):
        self.next_id += 1
        sent = self.send({"id": self.next_id, "method": method, "params": params})
        return self.next_id, sent

    def wait_for(self, matches, what):
        """The first message that `matches` and when it arrived; answers
        the server's own requests (progress tokens, configuration) on the way
        and keeps the other messages for a later wait."""
        for index, (arrived, message) in enumerate(self.pending):
            if matches(message):
                del self.pending[index]
                return self._checked(arrived, message, what)
        deadline = time.perf_counter() + self.timeout
        while True:
            left = deadline - time.perf_counter()
            if left <= 0:
                raise Failure(f"no {what} within {self.timeout} s")
            try:
                arrived, message = self.messages.get(timeout=left)
            except queue.Empty:
                continue
            if message is None:
                raise Failure(f"sfls closed its output ({self._status()}) while waiting for {what}")
            if "id" in message and "method" in message:
                self.send({"id": message["id"], "result": None})
            elif matches(message):
                return self._checked(arrived, message, what)
            elif message.get("method") != "window/logMessage":
                self.pending.append((arrived, message))

    def _status(self):
        try:
            return f"exit status {self.process.wait(timeout=1)}"
        except subprocess.TimeoutExpired:
            return "still running"

    @staticmethod
    def _checked(arrived, message, what):
        if "error" in message:
            raise Failure(f"{what}: error {message['error']}")
        return arrived, message

    def call(self, method, params):
        """Sends a request; returns its result and the seconds to its answer."""
        request_id, sent = self.request(method, params)
        arrived, message = self.wait_for(lambda m: m.get("id") == request_id, method)
        return message.get("result"), arrived - sent

    def peak_memory(self):
        with open(f"/proc/{self.process.pid}/status") as status:
            for line in status:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) * 1024
        return 0

    def close(self):
        try:
            self.call("shutdown", None)
            self.notify("exit", None)
            self.process.wait(timeout=self.timeout)
        except (Failure, OSError, subprocess.TimeoutExpired):
            self.process.kill()
            self.process.wait()


def edit_place(lines):
    """The line of a record's name near the middle of a scene file, and a
    matrix number of that record (its row 2, column 4) to hover on."""
    names = ("PLANE", "SPHERE", "CYLINDER", "CUBE")
    for index in range(len(lines) // 2, len(lines)):
        if lines[index].rstrip("\r") in names:
            row = lines[index + 3]
            column = len(" ".join(row.split()[:3])) + 1
            return index, (index + 3, column)
    raise Failure("no object record in the second half of the file")


def summary(values):
    return statistics.median(values), max(values)


def run(arguments):
    with open(arguments.file, "rb") as source:
        text = source.read().decode()
    lines = text.split("\n")
    edit_line, hover_at = edit_place(lines)
    name = lines[edit_line].rstrip("\r")
    uri = "file://" + os.path.abspath(arguments.file)
    document = {"uri": uri}

    client = Client([arguments.sfls], arguments.timeout)
    try:
        result, _ = client.call("initialize", {
            "processId": os.getpid(), "rootUri": None, "capabilities": {
                "textDocument": {"completion": {"completionItem": {"snippetSupport": True}},
                                 "publishDiagnostics": {"versionSupport": True}}}})
        sync = result["capabilities"].get("textDocumentSync", 1)
        incremental = (sync.get("change") if isinstance(sync, dict) else sync) == 2
        client.notify("initialized", {})

        version = 1

        def diagnostics_of(wanted_version, want_errors):
            def matches(message):
                if message.get("method") != "textDocument/publishDiagnostics":
                    return False
                params = message["params"]
                if params["uri"] != uri:
                    return False
                if "version" in params:
                    return params["version"] == wanted_version
                return bool(params["diagnostics"]) == want_errors
            return matches

        sent = client.notify("textDocument/didOpen", {"textDocument": {
            "uri": uri, "languageId": "scenefile", "version": version, "text": text}})
        arrived, _ = client.wait_for(diagnostics_of(version, False), "the first diagnostics")
        open_seconds = arrived - sent

        def edit(broken):
            nonlocal version
            version += 1
            new_name = name[:-1] if broken else name
            if incremental:
                # Removes the name's last letter, or puts it back.
                start = {"line": edit_line, "character": len(name) - 1}
                end = {"line": edit_line, "character": len(name) - (0 if broken else 1)}
                change = {"range": {"start": start, "end": end},
                          "text": "" if broken else name[-1]}
            else:
                lines[edit_line] = new_name
                change = {"text": "\n".join(lines)}
            return client.notify("textDocument/didChange", {
                "textDocument": {"uri": uri, "version": version}, "contentChanges": [change]})

        def timed_edit(broken):
            sent = edit(broken)
            arrived, _ = client.wait_for(diagnostics_of(version, broken),
                                         f"diagnostics of version {version}")
            return arrived - sent

        hover = ("textDocument/hover", {"textDocument": document, "position": {
            "line": hover_at[0], "character": hover_at[1]}})
        completion = ("textDocument/completion", {"textDocument": document, "position": {
            "line": edit_line - 1, "character": 0}})
        symbols = ("textDocument/documentSymbol", {"textDocument": document})
        figures = {key: [] for key in ("broken", "fixed", "hover", "completion", "symbols",
                                       "hover_busy", "completion_busy", "symbols_busy")}
        for _ in range(arguments.runs):
            figures["broken"].append(timed_edit(True))
            figures["fixed"].append(timed_edit(False))
            for key, (method, params) in (("hover", hover), ("completion", completion),
                                          ("symbols", symbols)):
                figures[key].append(client.call(method, params)[1])
                # The same request right behind an edit, while its check runs.
                broken = len(figures[key + "_busy"]) % 2 == 0
                edit(broken)
                figures[key + "_busy"].append(client.call(method, params)[1])
                client.wait_for(diagnostics_of(version, broken), f"diagnostics of version {version}")
                if broken:
                    edit(False)
                    client.wait_for(diagnostics_of(version, False),
                                    f"diagnostics of version {version}")
        print(f"file: {arguments.file}")
        print(f"bytes: {len(text.encode())}")
        print(f"runs: {arguments.runs}")
        print(f"incremental: {'yes' if incremental else 'no'}")
        print(f"open_s: {open_seconds:.4f}")
        for key, values in figures.items():
            median, maximum = summary(values)
            print(f"{key}_median_s: {median:.4f}")
            print(f"{key}_max_s: {maximum:.4f}")
        diagnostics = figures["broken"] + figures["fixed"]
        print(f"diagnostics_median_s: {statistics.median(diagnostics):.4f}")
        print(f"diagnostics_max_s: {max(diagnostics):.4f}")
        requests = [v for key in ("hover", "completion", "symbols") for v in figures[key]]
        busy = [v for key in ("hover", "completion", "symbols") for v in figures[key + "_busy"]]
        print(f"requests_idle_median_s: {statistics.median(requests):.4f}")
        print(f"requests_idle_max_s: {max(requests):.4f}")
        print(f"requests_busy_median_s: {statistics.median(busy):.4f}")
        print(f"requests_busy_max_s: {max(busy):.4f}")
        print(f"peak_bytes: {client.peak_memory()}")
    finally:
        client.close()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("sfls")
    parser.add_argument("file")
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--timeout", type=float, default=120)
    arguments = parser.parse_args()
    try:
        run(arguments)
    except Failure as failure:
        print(f"sfls_latency: {failure}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
