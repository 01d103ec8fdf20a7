#!/usr/bin/env bash
# Whether the lights' direction grids pay: bash bench/light_grids.sh [BUILD_DIR]
#
# render_probe time on floor scenes (`sfgen --layout floor -s 1`), the
# default scene and glass-mirror, at each size and samples a pixel, with the
# grids built and left out (--light-grids 1 and 0, alternated, RUNS times
# each, two threads). Prints a markdown table of the medians: the grids'
# build (finish_grids_s), the render with and without them (render_s), the
# camera samples an object, and whether RenderScene::lightGridsPay builds
# them (docs/TRACING.md, "Direction grids"). Fails if an image differs with
# and without them (rgb_fnv1a): the grids only find the same answers sooner.
#
# Environment: LIGHT_GRIDS_OBJECTS ("1000 100000 1000000"), LIGHT_GRIDS_SIZES
# ("1920x1080 1280x720"), LIGHT_GRIDS_SPPS ("1 4"), LIGHT_GRIDS_RUNS (3),
# LIGHT_GRIDS_SCENES (where floor-N.sf are taken from if there, else made:
# /tmp/scenefile-light-grids).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build}
[[ $build = /* ]] || build=$PWD/$build
bin=$build/bin
runs=${LIGHT_GRIDS_RUNS:-3}
scenes=${LIGHT_GRIDS_SCENES:-/tmp/scenefile-light-grids}

die() {
  echo "light_grids: $*" >&2
  exit 1
}
log() { echo "light_grids: $*" >&2; }
source "$root/bench/common.sh"
warn_unless_release "$build"
[[ -x $bin/render_probe && -x $bin/sfgen ]] || die "build render_probe and sfgen in $build first"
mkdir -p "$scenes"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

files=()
"$bin/render_probe" default-scene "$work/default.txt"
files+=("$work/default.txt" "$root/bench/scenes/glass-mirror.txt")
for n in ${LIGHT_GRIDS_OBJECTS-1000 100000 1000000}; do
  file=$scenes/floor-$n.sf
  [[ -f $file ]] || "$bin/sfgen" --layout floor -n "$n" -s 1 -o "$file" >/dev/null
  files+=("$file")
done

echo "| scene | objects | size | spp | samples an object | grids built | render with | render without | built by sfrender |"
echo "|---|---|---|---|---|---|---|---|---|"
for file in "${files[@]}"; do
  for size in ${LIGHT_GRIDS_SIZES:-1920x1080 1280x720}; do
    for spp in ${LIGHT_GRIDS_SPPS:-1 4}; do
      build_s=() with=() without=()
      for ((r = 0; r < runs; ++r)); do
        for grids in 1 0; do
          "$bin/render_probe" time "$file" --width "${size%x*}" --height "${size#*x}" \
            --spp "$spp" --threads 2 --light-grids "$grids" >"$work/$grids.txt"
        done
        [[ $(value rgb_fnv1a "$work/1.txt") == $(value rgb_fnv1a "$work/0.txt") ]] ||
          die "$(basename "$file") at $size, $spp spp: the image differs without the grids"
        build_s+=("$(value finish_grids_s "$work/1.txt")")
        with+=("$(value render_s "$work/1.txt")")
        without+=("$(value render_s "$work/0.txt")")
      done
      objects=$(value objects "$work/1.txt")
      samples=$(awk -v w="${size%x*}" -v h="${size#*x}" -v s="$spp" -v n="$objects" \
        'BEGIN { printf "%.1f", w * h * s / n }')
      "$bin/render_probe" time "$file" --width "${size%x*}" --height "${size#*x}" --spp "$spp" \
        --threads 2 >"$work/auto.txt"
      auto=no
      awk -v s="$(value finish_grids_s "$work/auto.txt")" 'BEGIN { exit !(s > 0) }' && auto=yes
      echo "| $(basename "$file") | $(thousands "$objects") | $size | $spp | $samples |" \
        "$(fmt 3 "$(median "${build_s[@]}")") s | $(fmt 3 "$(median "${with[@]}")") s |" \
        "$(fmt 3 "$(median "${without[@]}")") s | $auto |"
    done
  done
done
