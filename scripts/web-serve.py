#!/usr/bin/env python3
"""Serves the page (make web's build/web) on localhost.

With the headers that make it cross-origin isolated, so that it renders on
threads: Cross-Origin-Opener-Policy: same-origin, Cross-Origin-Embedder-Policy:
require-corp, Cross-Origin-Resource-Policy: same-origin. With --no-isolation,
as a host that neither sends them nor lets coi-serviceworker add them (its
script is answered empty): the page renders on one thread.
"""
import argparse
import functools
import http.server
import io
import os
import sys

ISOLATION_HEADERS = {
    "Cross-Origin-Opener-Policy": "same-origin",
    "Cross-Origin-Embedder-Policy": "require-corp",
    "Cross-Origin-Resource-Policy": "same-origin",
}
SERVICE_WORKER = "/coi-serviceworker.js"


class PageHandler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {
        **http.server.SimpleHTTPRequestHandler.extensions_map,
        ".wasm": "application/wasm",
        ".js": "text/javascript",
        ".mjs": "text/javascript",
        ".json": "application/json",
        ".css": "text/css",
        ".html": "text/html; charset=utf-8",
        ".sf": "text/plain; charset=utf-8",
        ".txt": "text/plain; charset=utf-8",
        ".pov": "text/plain; charset=utf-8",
        ".gltf": "model/gltf+json",
        ".glb": "model/gltf-binary",
    }

    def __init__(self, *args, isolation, **kwargs):
        self.isolation = isolation
        super().__init__(*args, **kwargs)

    def end_headers(self):
        # A rebuilt page is seen at the next load.
        self.send_header("Cache-Control", "no-cache")
        if self.isolation:
            for name, value in ISOLATION_HEADERS.items():
                self.send_header(name, value)
        super().end_headers()

    def send_head(self):
        if not self.isolation and self.path.split("?")[0] == SERVICE_WORKER:
            body = b"// Left out: this host is served without cross-origin isolation.\n"
            self.send_response(200)
            self.send_header("Content-Type", "text/javascript")
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            return io.BytesIO(body)
        return super().send_head()

    def log_message(self, format, *args):
        if self.verbose:
            super().log_message(format, *args)


def main():
    parser = argparse.ArgumentParser(description="Serve the scenefile page on localhost.")
    parser.add_argument("directory", help="the page's folder (make web: build/web)")
    parser.add_argument("--port", type=int, default=8043, help="port (default: 8043; 0: any free one)")
    parser.add_argument("--no-isolation", action="store_true",
                        help="serve without COOP/COEP and without the service worker that adds them: one thread")
    parser.add_argument("--verbose", action="store_true", help="log each request")
    args = parser.parse_args()

    if not os.path.isdir(args.directory):
        print(f"web-serve: {args.directory} is no folder (make web builds it)", file=sys.stderr)
        return 1
    PageHandler.verbose = args.verbose
    handler = functools.partial(PageHandler, directory=args.directory, isolation=not args.no_isolation)
    try:
        server = http.server.ThreadingHTTPServer(("127.0.0.1", args.port), handler)
    except OSError as error:
        print(f"web-serve: cannot listen on 127.0.0.1:{args.port}: {error.strerror}", file=sys.stderr)
        return 1
    mode = "cross-origin isolated: threads" if not args.no_isolation else "not isolated: one thread"
    print(f"Serving {args.directory} at http://127.0.0.1:{server.server_address[1]}/ ({mode})", flush=True)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    finally:
        server.server_close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
