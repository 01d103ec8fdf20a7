#!/usr/bin/env bash
# sfrender --tile i/4 and --region write exactly the pixels of the full
# render there: each tile's file equals the crop of the full image's file
# (oiiotool --cut, then --diff with no difference allowed), for uniform and
# adaptive sampling, with a seed, as PPM (16 bits) and as float EXR (with
# alpha too); and the four tiles of 4 cover the image, the first ones a row
# taller where the rows do not divide evenly.
#
# Usage: check_region_tiles.sh SFRENDER SCENE_FOLDER WORK_FOLDER
# Exit 77 (skipped) without oiiotool (Debian's openimageio-tools).
set -euo pipefail
sfrender=$(realpath "$1")
scenes=$(realpath "$2")
work=$3
if ! command -v oiiotool >/dev/null 2>&1; then
  echo "oiiotool is missing (Debian package openimageio-tools): skipped" >&2
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
cd "$work"

width=61
height=46  # 4 bands of 12, 12, 11 and 11 rows
failures=0

# add_comparison CROP FULL PART: adds the comparison of PART with FULL cut to CROP
# (WxH+X+Y) to those compare_all makes.
comparisons=()
add_comparison() {
  # The crop stays in memory, in the file's own pixel type. A region's EXR
  # keeps its place in the full image (its data window within the display
  # window: --crop); a PPM holds the pixels alone (--cut moves them to 0, 0).
  local cut=--cut
  [[ $3 == *.exr ]] && cut=--crop
  comparisons+=("$3" "$2" "$cut" "$1" --diff)
}

# compare_all: makes every comparison added since the last call in one
# oiiotool run (each run costs some 0.4 s of start-up); it fails if any
# part differs, and its report names the part.
compare_all() {
  if ! oiiotool --fail 0 --failpercent 0 "${comparisons[@]}" >diff.txt; then
    echo "FAIL: a part differs from its crop of the full image" >&2
    cat diff.txt >&2
    failures=$((failures + 1))
  fi
  comparisons=()
}

check() {
  local scene=$1 ext=$2
  shift 2
  local flags=(--quiet --width "$width" --height "$height" "$@")
  local scene_args=()
  [[ -n "$scene" ]] && scene_args=("$scene")
  "$sfrender" "${flags[@]}" -o "full.$ext" "${scene_args[@]}"
  local y=0
  for i in 0 1 2 3; do
    local rows=$(( i < 2 ? 12 : 11 ))
    "$sfrender" "${flags[@]}" --tile "$i/4" -o "tile$i.$ext" "${scene_args[@]}"
    add_comparison "${width}x${rows}+0+$y" "full.$ext" "tile$i.$ext"
    y=$((y + rows))
  done
  "$sfrender" "${flags[@]}" --region 7,5,40,31 -o "region.$ext" "${scene_args[@]}"
  add_comparison "33x26+7+5" "full.$ext" "region.$ext"
  compare_all
}

for ext in ppm exr; do
  bits=()
  [[ $ext == ppm ]] && bits=(--bits 16)
  check "" "$ext" "${bits[@]}" --spp 1
  check "" "$ext" "${bits[@]}" --spp 4 --seed 11
  check "$scenes/glass-mirror.txt" "$ext" "${bits[@]}" --spp 4
  check "$scenes/glass-mirror.txt" "$ext" "${bits[@]}" --spp 16 --adaptive 0.03 --threads 3
  check "" "$ext" "${bits[@]}" --spp 16 --adaptive 0.01 --seed 5
done
# PPM has no alpha: the coverage in EXR only.
check "" exr --spp 16 --adaptive 0.01 --seed 5 --alpha

# A region outside the image is refused as a usage error (exit 2).
set +e
"$sfrender" --quiet --width "$width" --height "$height" --region 0,0,62,10 -o bad.ppm 2>err.txt
status=$?
set -e
if [[ $status -ne 2 ]] || ! grep -q "sfrender: error: --region: " err.txt; then
  echo "FAIL: a region past the image gave exit $status: $(cat err.txt)" >&2
  failures=$((failures + 1))
fi
[[ $failures -eq 0 ]] || exit 1
echo "every tile and region equals the crop of the full image"
