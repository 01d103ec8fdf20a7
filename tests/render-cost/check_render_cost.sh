#!/usr/bin/env bash
# A render whose every hit both reflects and refracts (testdata/render-cost/):
# traced in full, its rays double at each bounce, 2^65 of them per pixel at
# --depth 64, and it never ends. Adaptive depth control (docs/RENDERING.md,
# "Cost") must finish it within SECONDS of wall time, with at most
# MAX_PER_PRIMARY reflected or refracted rays per primary ray (as --stats
# counts them), and write the image.
#
# Usage: check_render_cost.sh SFRENDER SCENE WORK WIDTH HEIGHT DEPTH SECONDS MAX_PER_PRIMARY
set -u

sfrender=$1
scene=$2
work=$3
width=$4
height=$5
depth=$6
max_seconds=$7
max_per_primary=$8

mkdir -p "$work"
image="$work/$(basename "$scene" .txt)-depth-$depth.ppm"
rm -f "$image"

start=$(date +%s%N)
timeout --signal=KILL "$max_seconds" "$sfrender" "$scene" -o "$image" --width "$width" \
  --height "$height" --depth "$depth" --threads 2 --quiet --stats >"$work/stdout" 2>"$work/stderr"
status=$?
end=$(date +%s%N)
elapsed_ms=$(((end - start) / 1000000))

if [ "$status" -ne 0 ]; then
  if [ "$status" -eq 137 ]; then
    echo "check_render_cost: sfrender ran past ${max_seconds} s at --depth $depth" >&2
  else
    echo "check_render_cost: sfrender exited with $status" >&2
  fi
  cat "$work/stderr" >&2
  exit 1
fi
if [ ! -s "$image" ]; then
  echo "check_render_cost: sfrender wrote no $image" >&2
  exit 1
fi

# "... (1,200 primary, 34,567 reflected or refracted, ...": the counts
# without their thousands separators.
stats=$(cat "$work/stdout" "$work/stderr")
primary=$(sed -n 's/.*(\([0-9,]*\) primary.*/\1/p' <<<"$stats" | tr -d ,)
secondary=$(sed -n 's/.* \([0-9,]*\) reflected or refracted.*/\1/p' <<<"$stats" | tr -d ,)
if [ -z "$primary" ] || [ -z "$secondary" ]; then
  echo "check_render_cost: no ray counts in sfrender --stats:" >&2
  echo "$stats" >&2
  exit 1
fi
echo "check_render_cost: ${elapsed_ms} ms, $primary primary, $secondary reflected or refracted"
if [ "$secondary" -gt "$((max_per_primary * primary))" ]; then
  echo "check_render_cost: $secondary reflected or refracted rays for $primary primary," \
    "more than $max_per_primary each" >&2
  exit 1
fi
