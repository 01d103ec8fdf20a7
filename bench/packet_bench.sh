#!/usr/bin/env bash
# Packet tracing against one ray at a time:
#   bash bench/packet_bench.sh [BUILD_DIR]
#
# Renders floor scenes of 1,000 and 100,000 objects (`sfgen --layout floor`)
# and the default scene (`render_probe default-scene`) at 1920x1080, 1 spp,
# depth 5, with `render_probe time --packets 1` and `--packets 0` alternately,
# ROUNDS times each, at 2 threads and at 1, and prints the median render
# times (parse and build apart) and their ratio. It stops if the two images
# differ (render_probe's rgb_fnv1a). The figures in
# docs/history/PERFORMANCE.md, "Packet tracing", are its output, with the instruction counts measured by
# hand (see there).
#
# Environment: ROUNDS (5), PACKET_BENCH_DIR (/tmp/scenefile-packet-bench).
set -euo pipefail

build=${1:-build}
bin=$build/bin
rounds=${ROUNDS:-5}
data=${PACKET_BENCH_DIR:-/tmp/scenefile-packet-bench}
for tool in sfgen render_probe; do
  [[ -x $bin/$tool ]] || {
    echo "packet_bench: $bin/$tool is missing: build first" >&2
    exit 1
  }
done
mkdir -p "$data"
for n in 1000 100000; do
  [[ -f $data/floor-$n.sf ]] ||
    "$bin/sfgen" --layout floor -n "$n" -s 1 --aspect 1.7777777777777777 -o "$data/floor-$n.sf" \
      >/dev/null
done
[[ -f $data/default.txt ]] || "$bin/render_probe" default-scene "$data/default.txt"

results=$(mktemp)
trap 'rm -f "$results"' EXIT
for threads in 2 1; do
  for scene in floor-1000.sf floor-100000.sf default.txt; do
    for round in $(seq "$rounds"); do
      for packets in 1 0; do
        out=$("$bin/render_probe" time "$data/$scene" --width 1920 --height 1080 --spp 1 \
          --depth 5 --threads "$threads" --packets "$packets")
        seconds=$(awk '/^render_s:/ { print $2 }' <<<"$out")
        hash=$(awk '/^rgb_fnv1a:/ { print $2 }' <<<"$out")
        echo "$scene $threads $packets $seconds $hash" >>"$results"
      done
    done
    hashes=$(awk -v s="$scene" -v t="$threads" '$1 == s && $2 == t { print $5 }' "$results" |
      sort -u | wc -l)
    [[ $hashes -eq 1 ]] || {
      echo "packet_bench: $scene: the images with and without packets differ" >&2
      exit 1
    }
  done
done

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
echo "| scene | threads | packets | one by one | ratio |"
echo "|---|---|---|---|---|"
for threads in 2 1; do
  for scene in floor-1000.sf floor-100000.sf default.txt; do
    with=$(awk -v s="$scene" -v t="$threads" '$1 == s && $2 == t && $3 == 1 { print $4 }' \
      "$results" | median)
    without=$(awk -v s="$scene" -v t="$threads" '$1 == s && $2 == t && $3 == 0 { print $4 }' \
      "$results" | median)
    awk -v s="$scene" -v t="$threads" -v a="$with" -v b="$without" \
      'BEGIN { printf "| %s | %s | %.3f s | %.3f s | %.3f |\n", s, t, a, b, a / b }'
  done
done
