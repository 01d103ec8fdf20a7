#!/usr/bin/env bash
# One render, written as PNG, TIFF and EXR (8 and 16 bits, half and float,
# with and without alpha), shows the same picture in a colour-managed
# reader: OpenImageIO's oiiotool converts each file to sRGB by what the file
# itself says of its colours (the PNG's sRGB chunk, the TIFF's sRGB tags, the
# EXR's linear values), to 8 bits, and every result agrees with the 8-bit
# PNG's within one level (1/255). An untagged copy of the TIFF must not agree:
# the agreement comes from the tags, not from the numbers happening to match.
#
# With --alpha, the straight colours and the alpha are compared: the integer
# files are read as they store them (straight; OpenImageIO would otherwise
# premultiply a PNG in linear light and a TIFF not), the EXR, premultiplied
# by convention, is unpremultiplied before its conversion.
#
# Usage: check_colour_managed.sh SFRENDER WORK_FOLDER
# Exit 77 (skipped) without oiiotool (Debian's openimageio-tools, which
# scripts/install-deps.sh installs).
set -euo pipefail
sfrender=$(realpath "$1")
work=$2
if ! command -v oiiotool >/dev/null 2>&1; then
  echo "oiiotool is missing (Debian package openimageio-tools): skipped" >&2
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
cd "$work"

straight=(--iconfig oiio:UnassociatedAlpha 1)

# render NAME FLAGS...: the default scene, small, with 4 samples a pixel so
# that edge pixels are partly covered.
render() {
  local name=$1
  shift
  "$sfrender" --quiet --width 160 --height 120 --spp 4 -o "$name" "$@"
}

# to_srgb FILE: FILE converted by oiiotool to 8-bit sRGB, as FILE.srgb.tif.
to_srgb() {
  local file=$1 read=()
  case $file in
    *alpha*.exr) read=("$file" --unpremult) ;;
    *alpha*) read=("${straight[@]}" "$file") ;;
    *) read=("$file") ;;
  esac
  oiiotool "${read[@]}" --tocolorspace sRGB -d uint8 -o "$file.srgb.tif"
}

# max_levels A B: the largest difference of two converted files, in 8-bit
# levels (oiiotool --diff reports it as a fraction of 1).
max_levels() {
  local report
  report=$(oiiotool "${straight[@]}" "$1" "${straight[@]}" "$2" --diff 2>&1 || true)
  if grep -q "PASS" <<<"$report" && ! grep -q "Max error" <<<"$report"; then
    echo 0
    return
  fi
  local max
  max=$(sed -n 's/.*Max error *= *\([0-9.e+-]*\).*/\1/p' <<<"$report" | head -1)
  if [[ -z $max ]]; then
    echo "cannot compare $1 and $2: $report" >&2
    exit 1
  fi
  awk -v m="$max" 'BEGIN { printf "%.3f\n", m * 255 }'
}

failed=0
# compare REFERENCE FILE: FILE's conversion within one level of REFERENCE's.
compare() {
  local levels
  levels=$(max_levels "$1.srgb.tif" "$2.srgb.tif")
  if awk -v l="$levels" 'BEGIN { exit !(l <= 1.001) }'; then
    echo "$2: within $levels levels of $1"
  else
    echo "$2: FAILS, $levels levels from $1" >&2
    failed=1
  fi
}

render plain.png
render plain-16.png --bits 16
render plain.tif
render plain-16.tif --bits 16
render plain.exr
render plain-half.exr --bits 16
render alpha.png --alpha
render alpha-16.png --alpha --bits 16
render alpha.tif --alpha
render alpha-16.tif --alpha --bits 16
render alpha.exr --alpha
render alpha-half.exr --alpha --bits 16
for file in plain*.png plain*.tif plain*.exr alpha*.png alpha*.tif alpha*.exr; do
  to_srgb "$file"
done
for file in plain-16.png plain.tif plain-16.tif plain.exr plain-half.exr; do
  compare plain.png "$file"
done
for file in alpha-16.png alpha.tif alpha-16.tif alpha.exr alpha-half.exr; do
  compare alpha.png "$file"
done

# The negative control: the TIFF with its tags erased reads as linear.
oiiotool plain.tif --eraseattrib "ICCProfile.*" --eraseattrib "Exif:ColorSpace" \
  --eraseattrib "oiio:ColorSpace" -o untagged.tif
to_srgb untagged.tif
levels=$(max_levels plain.png.srgb.tif untagged.tif.srgb.tif)
if awk -v l="$levels" 'BEGIN { exit !(l > 8) }'; then
  echo "untagged.tif: $levels levels from plain.png, as it should (no tags)"
else
  echo "untagged.tif: only $levels levels from plain.png: the comparison does not see the tags" >&2
  failed=1
fi
exit $failed
