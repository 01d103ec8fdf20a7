#!/bin/bash
# sfrender --tile i/N on separate processes, then --merge: the image one
# render makes, byte for byte as PNG and PPM, bit for bit as EXR pixels,
# whatever the order of the tiles; and --merge refuses what is not one
# image's regions. Arguments: BIN_DIR SOURCE_DIR WORK_DIR.
set -euo pipefail
bin=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
sfrender=$bin/sfrender
scene=$source/examples/red-sphere.sf
render=("$scene" --width 61 --height 47 --spp 4 -q)

"$sfrender" "${render[@]}" -o single.png
"$sfrender" "${render[@]}" -o single.ppm
"$sfrender" "${render[@]}" -o single.exr
for tile in 0 1 2 3 4; do "$sfrender" "${render[@]}" --tile "$tile/5" -o "tile-$tile.exr"; done
# The data window within the display window.
oiiotool --info -v tile-1.exr | grep -q "pixel data origin: x=0, y=10"
oiiotool --info -v tile-1.exr | grep -q "full/display size: 61 x 47"

"$sfrender" --merge tile-3.exr tile-0.exr tile-4.exr tile-2.exr tile-1.exr -o merged.png -q
"$sfrender" --merge tile-*.exr -o merged.ppm -q
"$sfrender" --merge tile-*.exr -o merged.exr -q
cmp merged.png single.png
cmp merged.ppm single.ppm
idiff -q -fail 0 -warn 0 merged.exr single.exr

# What it refuses: a missing tile, an image of another size, half floats,
# no output.
expect() {
  local status=$1 message=$2
  shift 2
  local got=0
  "$sfrender" "$@" 2>err.txt || got=$?
  if ((got != status)) || ! grep -q -- "$message" err.txt; then
    echo "sfrender $*: exit $got, expected $status and '$message'; it said:" >&2
    cat err.txt >&2
    exit 1
  fi
}
expect 1 "no region holds pixel 0,10 of the 61x47 image" --merge tile-0.exr tile-2.exr \
  tile-3.exr tile-4.exr -o gap.png
"$sfrender" "$scene" --width 61 --height 48 --tile 1/5 -o other.exr -q
expect 1 "is a region of a 61x48 at 0,0 image" --merge tile-0.exr other.exr -o mixed.png
"$sfrender" "${render[@]}" --tile 1/5 --bits 16 -o half.exr
expect 1 "holds 16-bit floating-point values" --merge tile-0.exr half.exr -o half.png
expect 2 "needs -o FILE" --merge tile-0.exr
expect 3 "cannot read 'absent.exr'" --merge absent.exr -o absent.png
[[ ! -e gap.png && ! -e mixed.png && ! -e half.png ]]
echo "tiles merged exactly; bad merges refused"
