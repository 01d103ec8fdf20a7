#!/bin/bash
# What splitting a render into tiles on separate processes costs
# (docs/SCALING.md): the 100,000-object floor scene at 640x360, rendered by
# one process and as 16 tiles one after another (each a whole sfrender:
# reading the scene, preparing it, its band of rows), the merge, and the
# scene's size and reading time, the figures that project to many nodes.
# Prints medians of RUNS runs (default 3) of wall and CPU seconds.
# Usage: bench/tiles_bench.sh BUILD_DIR [RUNS]
set -euo pipefail
bin=$(realpath "${1:-build}")/bin
runs=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$bin/sfgen" --layout floor -n 100000 -s 1 -o scene.sf >/dev/null
size=(--width 640 --height 360)

# seconds of wall, and of user + system CPU, of a command: "WALL CPU"
measure() {
  /usr/bin/time -f "%e %U %S" -o t.txt "$@" >/dev/null 2>&1
  awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }' t.txt
}
median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

one=() tiles_wall=() tiles_cpu=() merge=() read=() one_cpu=()
for ((run = 0; run < runs; ++run)); do
  read -r wall cpu < <(measure "$bin/sfrender" scene.sf "${size[@]}" -o one.exr -q)
  one+=("$wall") one_cpu+=("$cpu")
  total_wall=0 total_cpu=0
  for tile in $(seq 0 15); do
    read -r wall cpu < <(measure "$bin/sfrender" scene.sf "${size[@]}" --tile "$tile/16" \
      -o "tile-$tile.exr" -q)
    total_wall=$(awk "BEGIN { print $total_wall + $wall }")
    total_cpu=$(awk "BEGIN { print $total_cpu + $cpu }")
  done
  tiles_wall+=("$total_wall") tiles_cpu+=("$total_cpu")
  files=()
  for tile in $(seq 0 15); do files+=("tile-$tile.exr"); done
  read -r wall cpu < <(measure "$bin/sfrender" --merge "${files[@]}" -o merged.png -q)
  merge+=("$wall")
  read -r wall cpu < <(measure "$bin/sfcheck" -q scene.sf)
  read+=("$wall")
done
echo "scene: $(stat -c %s scene.sf) bytes, 100,000 objects; image 640x360"
echo "one process:        wall $(printf '%s\n' "${one[@]}" | median) s, CPU $(printf '%s\n' "${one_cpu[@]}" | median) s"
echo "16 tile processes:  wall $(printf '%s\n' "${tiles_wall[@]}" | median) s (one after another), CPU $(printf '%s\n' "${tiles_cpu[@]}" | median) s"
echo "merge of 16 tiles:  wall $(printf '%s\n' "${merge[@]}" | median) s"
echo "sfcheck (read):     wall $(printf '%s\n' "${read[@]}" | median) s"
echo "tile files:         $(du -cb tile-*.exr | tail -n 1 | cut -f1) bytes"
