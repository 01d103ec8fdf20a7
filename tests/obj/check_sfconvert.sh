#!/usr/bin/env bash
# sfconvert writes NAME.obj with NAME.mtl beside it (`mtllib NAME.mtl`),
# `--to obj` to standard output with no MTL, and every tool reads the OBJ
# back: sfconvert to the same scene file, sfcheck, sfrender. --no-loss
# refuses the camera and the lights that OBJ cannot hold.
# Usage: check_sfconvert.sh BIN_DIR SCENE WORK_DIR
set -euo pipefail
bin=$1
scene=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*"; exit 1; }
"$bin/sfconvert" "$scene" out.obj 2>err.txt
[ -f out.obj ] && [ -f out.mtl ] || fail "sfconvert wrote no out.obj and out.mtl"
grep -qx 'mtllib out.mtl' out.obj || fail "out.obj does not name out.mtl"
grep -q 'wrote out.obj (a Wavefront OBJ file, .*) and out.mtl' err.txt || fail "$(cat err.txt)"
grep -q '\[obj-write-loss\]' err.txt || fail "the camera and the lights are no losses"
"$bin/sfconvert" -q "$scene" - --to sf >expected.sf
"$bin/sfconvert" -q out.obj back.sf
cmp expected.sf back.sf || fail "out.obj does not read back to the scene"
"$bin/sfconvert" -q "$scene" - --to obj >stdout.obj
! grep -q '^mtllib' stdout.obj || fail "an OBJ on standard output names an MTL file"
"$bin/sfconvert" -q stdout.obj back2.sf
cmp expected.sf back2.sf || fail "the OBJ from standard output does not read back to the scene"
"$bin/sfcheck" out.obj >/dev/null 2>&1 || fail "sfcheck refuses out.obj"
"$bin/sfrender" -q out.obj -o out.png --width 32 --height 24 || fail "sfrender cannot render out.obj"
if "$bin/sfconvert" --no-loss "$scene" strict.obj 2>strict.txt; then fail "--no-loss wrote an OBJ"; fi
grep -q 'error: CAMERA is not written as OBJ' strict.txt || fail "$(cat strict.txt)"
[ ! -e strict.obj ] && [ ! -e strict.mtl ] || fail "--no-loss left a file behind"
echo "sfconvert writes out.obj and out.mtl, and every tool reads them back"
