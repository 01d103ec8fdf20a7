#!/usr/bin/env bash
# make web: the page in BUILD_DIR/web, static files only (docs/WEB.md).
# 1. libscene and the renderer compiled to WebAssembly by Debian's
#    emscripten, with and without threads (web/wasm/, its own CMake tree
#    in BUILD_DIR/web-wasm);
# 2. the page's scripts bundled by esbuild with the npm packages of web/.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(realpath -m "${1:-build}")"
jobs="${2:-$(nproc)}"
out="$build/web"

# Debian's emscripten works offline once its cache is writable: a copy of
# the packaged one, kept in the build folder. NODE_PATH finds Debian's acorn.
export EM_CACHE="$build/emscripten-cache"
if [ ! -d "$EM_CACHE" ]; then
  cp -r /usr/share/emscripten/cache "$EM_CACHE.partial"
  mv "$EM_CACHE.partial" "$EM_CACHE"
fi
export NODE_PATH=/usr/share/nodejs

# A unity build, as make build's: cold here, 2.3 min instead of 6.1.
emcmake cmake -S "$root" -B "$build/web-wasm" -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON \
  -DSCENEFILE_WEB_OUTPUT="$out" >/dev/null
cmake --build "$build/web-wasm" -j "$jobs"
node "$root/web/build.mjs" "$out"
echo "make web: the page is in $out (make web-serve serves it)" >&2
