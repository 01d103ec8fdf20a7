#!/usr/bin/env bash
# The language server's benchmark: bash bench/sfls_bench.sh [BUILD_DIR]   (or `make bench`)
#
# Generates scene files of 10,000 and 1,000,000 objects (sfgen, fixed seed)
# under /tmp unless they are there, and runs bench/sfls_latency.py, a
# scripted client, on each: diagnostics after an edit, hover, completion and
# documentSymbol idle and while a check runs, sfls's peak memory. It writes
# the table into docs/perf/RESULTS.md, between the markers of its own
# section; docs/PERFORMANCE.md ("The language server") sums it up.
#
# Environment: SFLS_BENCH_OBJECTS ("10000 1000000"), SFLS_BENCH_RUNS (10),
# BENCH_DIR (/tmp/scenefile-bench; never inside the repository).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build}
[[ $build = /* ]] || build=$PWD/$build
bin=$build/bin
sizes=${SFLS_BENCH_OBJECTS:-10000 1000000}
runs=${SFLS_BENCH_RUNS:-10}
data=${BENCH_DIR:-/tmp/scenefile-bench}
doc=$root/docs/perf/RESULTS.md

die() {
  echo "bench: $*" >&2
  exit 1
}
log() { echo "bench: $*" >&2; }
source "$root/bench/common.sh"

for tool in sfgen sfls; do
  [[ -x $bin/$tool ]] || die "$bin/$tool is missing: build first (cmake --build $build)"
done
mkdir -p "$data"
data=$(cd "$data" && pwd -P)
case "$data/" in
  "$(cd "$root" && pwd -P)"/*) die "BENCH_DIR $data is inside the repository; the scene files are large" ;;
esac
warn_unless_release "$build"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
calc() { awk "BEGIN { printf \"%s\", $1 }" </dev/null; }
ms() { fmt 1 "$(calc "$1 * 1000")"; }

rows=$work/rows.md
: >"$rows"
for objects in $sizes; do
  sf=$data/sfls-$objects.sf
  if [[ ! -f $sf || $bin/sfgen -nt $sf ]]; then
    log "generating $sf"
    "$bin/sfgen" -n "$objects" -s 1 -o "$sf" >&2
  fi
  log "sfls_latency.py --runs $runs $sf"
  out=$work/latency-$objects.txt
  python3 "$root/bench/sfls_latency.py" --runs "$runs" "$bin/sfls" "$sf" >"$out" ||
    die "sfls_latency.py failed on $sf"
  v() { value "$1" "$out"; }
  bytes=$(v bytes)
  cell() { echo "$(ms "$(v "$1_median_s")") ($(ms "$(v "$1_max_s")"))"; }
  echo "| $(thousands "$objects") | $(fmt 1 "$(calc "$bytes / 1e6")") MB | $(ms "$(v open_s)") |" \
    "$(cell diagnostics) | $(cell hover) / $(cell completion) / $(cell symbols) |" \
    "$(cell hover_busy) / $(cell completion_busy) / $(cell symbols_busy) |" \
    "$(fmt 1 "$(calc "$(v peak_bytes) / 1e6")") MB, $(fmt 2 "$(calc "$(v peak_bytes) / $bytes")")x |" >>"$rows"
  incremental=$(v incremental)
done

section=$work/section.md
{
  echo '<!-- BEGIN sfls-latency: written by bench/sfls_bench.sh; edits here are lost -->'
  echo "## The language server"
  echo
  echo "Measured on $(date -u +%Y-%m-%d) with \`bash bench/sfls_bench.sh\`: $(nproc) logical CPUs," \
    "CPU \"$(cpu_model)\", $(memory_total) of memory, ${build_type:-unknown} build," \
    "commit $(short_commit "$root"). The scenes are \`sfgen -n N -s 1\`; incremental edits:" \
    "$incremental. Times in ms, median (max) of $runs runs of each; diagnostics are the" \
    "$((2 * runs)) edits that break a record's name and put it back, each timed from its" \
    "didChange to the publishDiagnostics of its version; \"busy\" requests are sent right" \
    "after such an edit. Memory is sfls's VmHWM against the document's size."
  echo
  echo "| objects | file | first diagnostics | diagnostics after an edit | hover / completion / symbols, idle | the same, busy | peak memory |"
  echo "|---|---|---|---|---|---|---|"
  cat "$rows"
  echo '<!-- END sfls-latency -->'
} >"$section"
replace_section sfls-latency "$section"
cat "$section"
