#!/bin/bash
# sfrender-tiles.sh's last job, run once every tile has succeeded
# (afterok): the tiles put together into the image (sfrender --merge).
# Arguments: SFRENDER N WORK OUTPUT [MERGE FLAGS...] (--bits, --no-clobber,
# -q, -v: those of sfrender-tiles.sh's flags that shape the image written).
set -u
sfrender=$1 tiles=$2 work=$3 output=$4
shift 4
files=()
for ((tile = 0; tile < tiles; ++tile)); do files+=("$work/tile-$tile.exr"); done
exec "$sfrender" --merge "${files[@]}" -o "$output" "$@"
