#!/usr/bin/env bash
# The page's benchmark: bash bench/web_bench.sh [BUILD_DIR]   (or `make bench`)
#
# In headless Chromium (Debian's, driven by tests/web's playwright-core) on
# this machine, bench/web_bench.mjs measures, median of WEB_BENCH_RUNS:
# the time from navigation start to the page's first image and to its 1 spp
# image of the default scene at 640x480 (cross-origin isolated, with
# threads, and not); the bytes the page downloads, gzip -9 (the first load
# and the whole folder); and window.scenefile.render against sfrender on the
# same scene, size, samples and threads. It prints a markdown table
# (docs/WEB.md, "Speed", holds the latest). Skipped, with a message, when the
# page was not built (make web) or Chromium is missing.
#
# Environment: WEB_BENCH_RUNS (5), WEB_BENCH_EXAMPLE (docs/guide/transparency.txt).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build}
[[ $build = /* ]] || build=$PWD/$build
runs=${WEB_BENCH_RUNS:-5}
example=${WEB_BENCH_EXAMPLE:-$root/docs/guide/transparency.txt}

log() { echo "bench: $*" >&2; }
source "$root/bench/common.sh"

if [[ ! -f $build/web/index.html ]]; then
  log "skipped the page's benchmark: $build/web is not built (make web)"
  exit 0
fi
if [[ ! -x /usr/bin/chromium || ! -d $root/tests/web/node_modules/playwright-core ]]; then
  log "skipped the page's benchmark: Chromium or tests/web's npm packages are missing" \
    "(scripts/install-deps.sh installs them)"
  exit 0
fi
warn_unless_release "$build"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=$work/web.txt
log "web_bench.mjs: $runs runs of each"
node "$root/bench/web_bench.mjs" "$build" "$runs" default "$example" >"$out"
v() { value "$1" "$out"; }
ms() { fmt 0 "$(awk -v s="$1" 'BEGIN { print s * 1000 }')"; }
kb() { fmt 0 "$(awk -v b="$1" 'BEGIN { print b / 1000 }')"; }
ratio() { fmt 2 "$(awk -v a="$1" -v b="$2" 'BEGIN { print a / b }')"; }

echo "Measured on $(date -u +%Y-%m-%d) with \`bash bench/web_bench.sh\`: headless" \
  "$(/usr/bin/chromium --version 2>/dev/null | head -n 1), $(nproc) logical CPUs," \
  "CPU \"$(cpu_model)\", commit $(short_commit "$root"); median of $runs (load times: max" \
  "in parentheses), a fresh browser context each load."
echo
echo "| load, default scene at 640x480 | first image | 1 spp image |"
echo "|---|---|---|"
for key in isolated not_isolated; do
  label="cross-origin isolated ($(v threads_available) threads)"
  [[ $key == isolated ]] || label="not isolated (1 thread)"
  echo "| $label | $(ms "$(v load_${key}_first_s)") ms ($(ms "$(v load_${key}_first_max_s)")) |" \
    "$(ms "$(v load_${key}_1spp_s)") ms ($(ms "$(v load_${key}_1spp_max_s)")) |"
done
echo
echo "| download, gzip -9 | bytes |"
echo "|---|---|"
echo "| first load ($(v files_first_load | wc -w) files) | $(kb "$(v bytes_first_load_gzip)") kB |"
echo "| the whole page ($(v files_total) files) | $(kb "$(v bytes_total_gzip)") kB |"
echo
echo "| render at 640x480 | WebAssembly | sfrender | ratio |"
echo "|---|---|---|---|"
for scene in default "$(basename "$example")"; do
  for spp in 1 16; do
    for threads in 1 2; do
      key=render_${scene}_spp${spp}_t${threads}
      wasm=$(v "${key}_wasm_s")
      native=$(v "${key}_native_s")
      echo "| $scene, $spp spp, $threads thread$([[ $threads == 1 ]] || echo s) |" \
        "$(ms "$wasm") ms | $(ms "$native") ms | $(ratio "$wasm" "$native") |"
    done
  done
done
echo
echo "First load: $(v files_first_load)."
