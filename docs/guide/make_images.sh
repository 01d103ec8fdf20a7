#!/usr/bin/env bash
# The pictures of docs/GUIDE.md, made from the scenes in the repository:
#
#   make_images.sh BIN_DIR OUT_DIR     every picture (cmake --build BUILD --target docs-images)
#   make_images.sh --check BIN_DIR     sfrender's pictures made again in a temporary
#                                      folder, each byte-identical to docs/images/guide's,
#                                      and sfcheck's diagnostic quoted in GUIDE.md as it prints it
#                                      (ctest docs.guide-images)
#
# BIN_DIR holds sfrender, sfconvert and sfcheck. POV-Ray's and Blender's
# pictures are made where povray and blender are installed, and left as they
# are otherwise; --check skips them (their bytes follow those programs'
# versions, not this project).
set -euo pipefail

guide=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$guide/../.." && pwd)
committed=$root/docs/images/guide
check=false
if [[ ${1:-} == --check ]]; then
  check=true
  shift
fi
bin=${1:?usage: make_images.sh [--check] BIN_DIR [OUT_DIR]}
bin=$(cd "$bin" && pwd)
if $check; then
  out=$(mktemp -d "${TMPDIR:-/tmp}/scenefile-guide.XXXXXX")
  trap 'rm -rf "$out"' EXIT
else
  out=${2:?usage: make_images.sh BIN_DIR OUT_DIR}
  mkdir -p "$out"
  out=$(cd "$out" && pwd)
fi

# One size for every picture: small files, and a 16:9 frame.
width=480
height=270
size=(--width "$width" --height "$height")

# sfrender's pictures, 4 samples a pixel for smooth edges.
render() { # [SCENE] PNG: no scene is sfrender's built-in one
  local png=${*: -1}
  "$bin/sfrender" "${@:1:$#-1}" -o "$out/$png" "${size[@]}" --spp 4 --quiet
}
render default-scene.png
for example in "$root"/examples/*.sf "$root"/examples/*.txt; do
  name=$(basename "$example")
  render "$example" "example-${name%.*}.png"
done
render "$guide/first-scene.sf" first-scene-sf.png
render "$guide/first-scene.txt" first-scene.png
for row in ambient specular shininess reflectivity transparency ri; do
  render "$guide/$row.txt" "row-$row.png"
done

if $check; then
  failures=0
  for made in "$out"/*.png; do
    name=$(basename "$made")
    if ! cmp -s "$made" "$committed/$name"; then
      echo "FAIL: docs/images/guide/$name differs from what sfrender draws now (make docs makes it again)"
      failures=$((failures + 1))
    fi
  done
  # The diagnostic that GUIDE.md shows, line by line as sfcheck prints it.
  while IFS= read -r line; do
    if ! grep -qxF -- "$line" "$root/docs/GUIDE.md"; then
      echo "FAIL: docs/GUIDE.md does not quote sfcheck's line: $line"
      failures=$((failures + 1))
    fi
  done < <(cd "$guide" && "$bin/sfcheck" first-scene-mistakes.txt 2>&1 || true)
  ((failures == 0)) || exit 1
  echo "PASS: $(ls "$out" | wc -l) pictures as committed, and sfcheck's diagnostic as quoted"
  exit 0
fi

# The same scene through sfconvert, drawn by POV-Ray and by Blender (Cycles).
# Both write the time of the render into their PNG; without it the same
# picture is the same bytes, and make docs leaves the committed file alone.
without_metadata() { # PNG
  command -v oiiotool >/dev/null || return 0
  oiiotool "$1" --nosoftwareattrib --eraseattrib ".*" -o "$1.tmp.png"
  mv "$1.tmp.png" "$1"
}
# The converted files in a folder of their own, which POV-Ray, writing only
# into its working folder, renders in.
converted=$(mktemp -d "${TMPDIR:-/tmp}/scenefile-guide.XXXXXX")
trap 'rm -rf "$converted"' EXIT
"$bin/sfconvert" "$guide/first-scene.txt" "$converted/first-scene.pov" "${size[@]}" --quiet
"$bin/sfconvert" "$guide/first-scene.txt" "$converted/first-scene.gltf" "${size[@]}" --quiet
if command -v povray >/dev/null; then
  (cd "$converted" && povray +Ifirst-scene.pov +Opovray.png "+W$width" "+H$height" \
     +A -D -V File_Gamma=1.0 >/dev/null 2>&1)
  without_metadata "$converted/povray.png"
  mv "$converted/povray.png" "$out/first-scene-povray.png"
else
  echo "make_images.sh: povray is not installed; first-scene-povray.png left as it is" >&2
fi
if command -v blender >/dev/null; then
  blender -b --factory-startup --python-exit-code 1 --python "$guide/blender_render.py" \
    -- "$converted/first-scene.gltf" "$converted/blender.png" "$width" "$height" >/dev/null 2>&1
  without_metadata "$converted/blender.png"
  mv "$converted/blender.png" "$out/first-scene-blender.png"
else
  echo "make_images.sh: blender is not installed; first-scene-blender.png left as it is" >&2
fi
